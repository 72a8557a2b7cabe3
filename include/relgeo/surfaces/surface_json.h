// relgeo/surfaces/surface_json.h — a small JSON format for NURBS surfaces,
// curves, trimmed faces and surface models (nlohmann-json through relgeo/io:
// link relgeo::io).
//
// Format (doc/joining.md, "JSON surface format"); numbers are JSON numbers
// (read as doubles, written so that they read back bit for bit):
//
//   { "format": "relgeo-surface-model", "version": 1,
//     "edges": [ {"curve": CURVE3} | {"polyline": [[x,y,z], ...]} | {} ],
//     "faces": [ { "surface": SURFACE, "reversed": false,
//                  "outer": [TRIM, ...],            (omitted: the whole parameter rectangle)
//                  "inner": [[TRIM, ...], ...] } ] }
//   SURFACE = { "degree_u": p, "degree_v": q, "count_u": nu, "count_v": nv,
//               "knots_u": [...], "knots_v": [...],
//               "control_points": [[x,y,z], ...]   (nu * nv, row-major: index i * nv + j, i along u)
//               "weights": [...] }                  (optional: rational)
//   CURVE3 / CURVE2 = { "degree": p, "knots": [...], "control_points": [[x,y(,z)], ...], "weights": [...] }
//   TRIM = { "polyline": [[u,v], ...] } or { "curve": CURVE2 },
//          plus optional "reversed": bool and "edge": index into "edges".
//
// Reading validates everything (the constructors' typed errors); a file that
// is missing or not JSON is relgeo/io's Unreadable_file / io::Parse_error
// (with the line), one that lacks a field Unreadable_file naming the field, a
// number beyond double's range Non_finite_input.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/io/json.h"
#include "relgeo/io/text_file.h"
#include "relgeo/surfaces/nurbs_curve.h"
#include "relgeo/surfaces/nurbs_surface.h"
#include "relgeo/surfaces/surface_model.h"
#include "relgeo/surfaces/trimmed_surface.h"

namespace relgeo {

namespace internal {

inline const nlohmann::json& json_field(const nlohmann::json& j, const char* key, const std::string& where) {
  if (!j.is_object() || !j.contains(key)) throw Unreadable_file(where + ": missing field '" + key + "'");
  return j.at(key);
}
inline std::vector<double> json_numbers(const nlohmann::json& j, const std::string& where) {
  if (!j.is_array()) throw Unreadable_file(where + ": expected an array of numbers");
  std::vector<double> v;
  for (const auto& x : j) {
    if (!x.is_number()) throw Unreadable_file(where + ": expected a number");
    v.push_back(x.get<double>());
  }
  return v;
}
template <int D>
std::vector<Vector_nd<double, D>> json_points(const nlohmann::json& j, const std::string& where) {
  if (!j.is_array()) throw Unreadable_file(where + ": expected an array of points");
  std::vector<Vector_nd<double, D>> pts;
  for (const auto& p : j) {
    const std::vector<double> c = json_numbers(p, where);
    if (c.size() != static_cast<std::size_t>(D))
      throw Unreadable_file(where + ": a point with " + std::to_string(c.size()) + " coordinates, expected " +
                            std::to_string(D));
    Vector_nd<double, D> v;
    for (int i = 0; i < D; ++i) v[i] = c[i];
    pts.push_back(v);
  }
  return pts;
}
inline int json_int(const nlohmann::json& j, const char* key, const std::string& where) {
  const auto& v = json_field(j, key, where);
  if (!v.is_number_integer()) throw Unreadable_file(where + ": field '" + key + "' must be an integer");
  return v.get<int>();
}

}  // namespace internal

/// A NURBS curve of dimension D from its JSON object.
template <int D>
Nurbs_curve<double, D> nurbs_curve_from_json(const nlohmann::json& j, const std::string& where = "curve") {
  std::vector<typename Nurbs_curve<double, D>::Point> pts;
  for (const auto& v : internal::json_points<D>(internal::json_field(j, "control_points", where), where))
    pts.push_back(internal::to_point(v));
  std::vector<double> w;
  if (j.contains("weights")) w = internal::json_numbers(j.at("weights"), where + ".weights");
  return Nurbs_curve<double, D>(internal::json_int(j, "degree", where),
                                internal::json_numbers(internal::json_field(j, "knots", where), where + ".knots"),
                                std::move(pts), std::move(w));
}

template <int D>
nlohmann::json to_json(const Nurbs_curve<double, D>& c) {
  nlohmann::json j;
  j["degree"] = c.degree();
  j["knots"] = c.knots();
  nlohmann::json pts = nlohmann::json::array();
  for (const auto& p : c.control_points()) pts.push_back(internal::to_vector(p));
  j["control_points"] = pts;
  if (c.is_rational()) j["weights"] = c.weights();
  return j;
}

inline Nurbs_surface<double> nurbs_surface_from_json(const nlohmann::json& j, const std::string& where = "surface") {
  std::vector<Point_3<double>> pts;
  for (const auto& v : internal::json_points<3>(internal::json_field(j, "control_points", where), where))
    pts.push_back(internal::to_point(v));
  std::vector<double> w;
  if (j.contains("weights")) w = internal::json_numbers(j.at("weights"), where + ".weights");
  const int nu = internal::json_int(j, "count_u", where), nv = internal::json_int(j, "count_v", where);
  if (nu < 0 || nv < 0) throw Unreadable_file(where + ": negative control point count");
  return Nurbs_surface<double>(internal::json_int(j, "degree_u", where), internal::json_int(j, "degree_v", where),
                               internal::json_numbers(internal::json_field(j, "knots_u", where), where + ".knots_u"),
                               internal::json_numbers(internal::json_field(j, "knots_v", where), where + ".knots_v"),
                               static_cast<std::size_t>(nu), static_cast<std::size_t>(nv), std::move(pts),
                               std::move(w));
}

inline nlohmann::json to_json(const Nurbs_surface<double>& s) {
  nlohmann::json j;
  j["degree_u"] = s.degree_u(), j["degree_v"] = s.degree_v();
  j["count_u"] = s.count_u(), j["count_v"] = s.count_v();
  j["knots_u"] = s.knots_u(), j["knots_v"] = s.knots_v();
  nlohmann::json pts = nlohmann::json::array();
  for (const auto& p : s.control_points()) pts.push_back(internal::to_vector(p));
  j["control_points"] = pts;
  if (s.is_rational()) j["weights"] = s.weights();
  return j;
}

namespace internal {
inline Trim_loop trim_loop_from_json(const nlohmann::json& j, const std::string& where) {
  if (!j.is_array()) throw Unreadable_file(where + ": expected an array of trim curves");
  Trim_loop loop;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const auto& c = j[i];
    const std::string w = where + "[" + std::to_string(i) + "]";
    Trim_curve t;
    if (c.contains("polyline")) {
      std::vector<Point_2<double>> pl;
      for (const auto& v : json_points<2>(c.at("polyline"), w)) pl.push_back(to_point(v));
      t.geometry = std::move(pl);
    } else {
      t.geometry = nurbs_curve_from_json<2>(json_field(c, "curve", w), w);
    }
    if (c.contains("reversed")) t.reversed = c.at("reversed").get<bool>();
    if (c.contains("edge")) t.edge = c.at("edge").get<int>();
    loop.curves.push_back(std::move(t));
  }
  return loop;
}
inline nlohmann::json to_json(const Trim_loop& loop) {
  nlohmann::json j = nlohmann::json::array();
  for (const Trim_curve& t : loop.curves) {
    nlohmann::json c;
    if (t.is_polyline()) {
      nlohmann::json pl = nlohmann::json::array();
      for (const auto& p : std::get<0>(t.geometry)) pl.push_back(to_vector(p));
      c["polyline"] = pl;
    } else {
      c["curve"] = relgeo::to_json(std::get<1>(t.geometry));
    }
    if (t.reversed) c["reversed"] = true;
    if (t.edge >= 0) c["edge"] = t.edge;
    j.push_back(c);
  }
  return j;
}
}  // namespace internal

/// A surface model from parsed JSON. \throws Unreadable_file for a missing or
/// mistyped field; the constructors' typed errors for inconsistent data.
inline Surface_model surface_model_from_json(const nlohmann::json& j, const std::string& where = "surface model") {
  if (!j.is_object()) throw Unreadable_file(where + ": expected a JSON object");
  if (j.contains("format") && j.at("format") != "relgeo-surface-model")
    throw Unreadable_file(where + ": format is not relgeo-surface-model");
  Surface_model m;
  if (j.contains("edges"))
    for (std::size_t i = 0; i < j.at("edges").size(); ++i) {
      const auto& e = j.at("edges")[i];
      const std::string w = where + ".edges[" + std::to_string(i) + "]";
      Model_edge edge;
      if (e.contains("curve")) edge.curve = nurbs_curve_from_json<3>(e.at("curve"), w);
      else if (e.contains("polyline"))
        for (const auto& v : internal::json_points<3>(e.at("polyline"), w)) edge.polyline.push_back(internal::to_point(v));
      m.edges.push_back(std::move(edge));
    }
  const auto& faces = internal::json_field(j, "faces", where);
  if (!faces.is_array()) throw Unreadable_file(where + ": 'faces' must be an array");
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const auto& f = faces[i];
    const std::string w = where + ".faces[" + std::to_string(i) + "]";
    Nurbs_surface<double> s = nurbs_surface_from_json(internal::json_field(f, "surface", w), w + ".surface");
    const bool reversed = f.contains("reversed") && f.at("reversed").get<bool>();
    if (!f.contains("outer")) {
      m.faces.push_back(Trimmed_surface::untrimmed(std::move(s), reversed));
      continue;
    }
    Trim_loop outer = internal::trim_loop_from_json(f.at("outer"), w + ".outer");
    std::vector<Trim_loop> inner;
    if (f.contains("inner"))
      for (std::size_t k = 0; k < f.at("inner").size(); ++k)
        inner.push_back(internal::trim_loop_from_json(f.at("inner")[k], w + ".inner[" + std::to_string(k) + "]"));
    m.faces.emplace_back(std::move(s), std::move(outer), std::move(inner), reversed);
  }
  (void)m.edge_uses();  // every edge index names an edge
  return m;
}

inline nlohmann::json to_json(const Surface_model& m) {
  nlohmann::json j;
  j["format"] = "relgeo-surface-model";
  j["version"] = 1;
  j["edges"] = nlohmann::json::array();
  for (const Model_edge& e : m.edges) {
    nlohmann::json je = nlohmann::json::object();
    if (e.curve) je["curve"] = to_json(*e.curve);
    else if (!e.polyline.empty()) {
      nlohmann::json pl = nlohmann::json::array();
      for (const auto& p : e.polyline) pl.push_back(internal::to_vector(p));
      je["polyline"] = pl;
    }
    j["edges"].push_back(je);
  }
  j["faces"] = nlohmann::json::array();
  for (const Trimmed_surface& f : m.faces) {
    nlohmann::json jf;
    jf["surface"] = to_json(f.surface());
    if (f.reversed()) jf["reversed"] = true;
    jf["outer"] = internal::to_json(f.outer_loop());
    if (!f.inner_loops().empty()) {
      jf["inner"] = nlohmann::json::array();
      for (const Trim_loop& l : f.inner_loops()) jf["inner"].push_back(internal::to_json(l));
    }
    j["faces"].push_back(jf);
  }
  return j;
}

/// Reads a surface model file. \throws Unreadable_file (missing file, not
/// JSON: io::Parse_error with the line, missing field), Non_finite_input, or
/// the typed errors of invalid data.
inline Surface_model read_surface_model_json(const std::string& path) {
  const nlohmann::json j = io::parse_json(io::read_text_file(path, "surface file"), path);
  try {
    return surface_model_from_json(j, path);
  } catch (const nlohmann::json::exception& e) {
    throw Unreadable_file("surface file '" + path + "': " + e.what());
  }
}

/// \brief Gives model edges their 3D curves from a JSON file (thesis case 1
/// for edges a model lacks them):
///   { "edges": [ {"edge": 0, "curve": CURVE3} | {"edge": 2, "polyline": [[x,y,z], ...]} ] }
/// \throws Unreadable_file (missing, not JSON, missing field), Invalid_input
/// for an edge index the model does not have.
inline void read_edge_curves_json(const std::string& path, Surface_model& m) {
  const nlohmann::json j = io::parse_json(io::read_text_file(path, "curve file"), path);
  try {
    const auto& edges = internal::json_field(j, "edges", path);
    if (!edges.is_array()) throw Unreadable_file(path + ": 'edges' must be an array");
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const std::string w = path + ".edges[" + std::to_string(i) + "]";
      const int e = internal::json_int(edges[i], "edge", w);
      if (e < 0 || static_cast<std::size_t>(e) >= m.edges.size())
        throw Invalid_input(w + ": the model has no edge " + std::to_string(e));
      Model_edge edge;
      if (edges[i].contains("curve")) edge.curve = nurbs_curve_from_json<3>(edges[i].at("curve"), w);
      else
        for (const auto& v : internal::json_points<3>(internal::json_field(edges[i], "polyline", w), w))
          edge.polyline.push_back(internal::to_point(v));
      m.edges[static_cast<std::size_t>(e)] = std::move(edge);
    }
  } catch (const nlohmann::json::exception& e) {
    throw Unreadable_file("curve file '" + path + "': " + e.what());
  }
}

/// Writes a surface model file. \throws io::Unwritable_file.
inline void write_surface_model_json(const Surface_model& m, const std::string& path) {
  io::write_text_file(path, to_json(m).dump(1) + "\n", "surface file");
}

}  // namespace relgeo
