// relgeo/surfaces/occt_io.h — trimmed NURBS faces from STEP and IGES files
// through OpenCASCADE (link relgeo::occt), and the writers the tests use to
// make their own files.
#pragma once

#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

#include "relgeo/core/errors.h"
#include "relgeo/surfaces/occt_conversion.h"
#include "relgeo/surfaces/surface_model.h"

namespace relgeo {

namespace internal {

/// OpenCASCADE's readers and writers report progress on the default
/// messenger's console printer; silence it for the scope (restored after).
class Quiet_occt_messenger {
 public:
  Quiet_occt_messenger() : messenger_(Message::DefaultMessenger()) {
    saved_ = messenger_->Printers();
    messenger_->ChangePrinters().Clear();
  }
  ~Quiet_occt_messenger() { messenger_->ChangePrinters() = saved_; }
  Quiet_occt_messenger(const Quiet_occt_messenger&) = delete;
  Quiet_occt_messenger& operator=(const Quiet_occt_messenger&) = delete;

 private:
  Handle(Message_Messenger) messenger_;
  Message_SequenceOfPrinters saved_;
};

template <class Reader>
TopoDS_Shape read_occt_shape(Reader& reader, const std::string& path, const char* kind) {
  if (!std::filesystem::is_regular_file(path)) throw Unreadable_file(std::string("cannot open ") + kind + " file '" + path + "'");
  const Quiet_occt_messenger quiet;
  try {
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
      throw Unreadable_file(std::string("cannot parse ") + kind + " file '" + path + "'");
    if (reader.TransferRoots() <= 0)
      throw Unreadable_file(std::string(kind) + " file '" + path + "' holds no shape OpenCASCADE can transfer");
    TopoDS_Shape s = reader.OneShape();
    if (s.IsNull()) throw Unreadable_file(std::string(kind) + " file '" + path + "' holds no shape");
    return s;
  } catch (const Standard_Failure& e) {
    throw Unreadable_file(std::string("OpenCASCADE failed on ") + kind + " file '" + path + "': " + e.GetMessageString());
  }
}

}  // namespace internal

/// The shape of a STEP file. \throws Unreadable_file.
inline TopoDS_Shape read_step_shape(const std::string& path) {
  STEPControl_Reader reader;
  return internal::read_occt_shape(reader, path, "STEP");
}
/// The shape of an IGES file. \throws Unreadable_file.
inline TopoDS_Shape read_iges_shape(const std::string& path) {
  IGESControl_Reader reader;
  return internal::read_occt_shape(reader, path, "IGES");
}

/// \brief The trimmed faces of a STEP (.step, .stp) or IGES (.iges, .igs)
/// file as a surface model (surface_model_from_shape), chosen by extension.
/// \throws Unreadable_file (missing, unparsable, no face, unknown extension),
/// or the typed errors of faces relgeo refuses.
inline Surface_model read_cad_model(const std::string& path, const Occt_read_options& options = {}) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  TopoDS_Shape shape;
  if (ext == ".step" || ext == ".stp") shape = read_step_shape(path);
  else if (ext == ".iges" || ext == ".igs") shape = read_iges_shape(path);
  else throw Unreadable_file("'" + path + "': unknown CAD extension (expected .step, .stp, .iges or .igs)");
  try {
    return surface_model_from_shape(shape, options);
  } catch (const Unreadable_file&) {
    throw;
  } catch (const Invalid_input& e) {
    if (std::string(e.what()).find("no face") != std::string::npos)
      throw Unreadable_file("'" + path + "' holds no face");
    throw;
  }
}

/// Writes a shape as STEP (AP214, as is). \throws Unreadable_file when the
/// file cannot be written.
inline void write_step_shape(const TopoDS_Shape& shape, const std::string& path) {
  const internal::Quiet_occt_messenger quiet;
  STEPControl_Writer writer;
  if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone || writer.Write(path.c_str()) != IFSelect_RetDone)
    throw Unreadable_file("cannot write STEP file '" + path + "'");
}
/// Writes a shape as IGES (B-rep mode: faces, edges and their sharing).
inline void write_iges_shape(const TopoDS_Shape& shape, const std::string& path) {
  const internal::Quiet_occt_messenger quiet;
  IGESControl_Controller::Init();
  IGESControl_Writer writer("MM", 1);  // 1: B-rep entities (faces with shared edges)
  if (!writer.AddShape(shape)) throw Unreadable_file("IGES: cannot translate the shape for '" + path + "'");
  writer.ComputeModel();
  if (!writer.Write(path.c_str())) throw Unreadable_file("cannot write IGES file '" + path + "'");
}

}  // namespace relgeo
