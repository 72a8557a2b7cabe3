// The bad-input catalogue (test/data/bad/, doc/reliability.md): one test per
// file, asserting the documented behaviour — a typed error that names the
// defect and where it is, or (for files that read fine) the defect that
// check_mesh, check_solid or Loop subdivision reports. Each test prints one
// line "CATALOGUE | file | observed behaviour" (the table of the manual).
//
// Readers must also fail fast on huge counts: allocation_tracker.cpp
// records the largest single allocation, which must stay small.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <typeinfo>
#include <vector>

#include "allocation_tracker.h"
#include "relgeo/error.h"
#include "relgeo/hull.h"
#include "relgeo/io/point_file.h"
#include "relgeo/kernel.h"
#include "relgeo/mesh/mesh_io.h"
#include "relgeo/mesh/self_intersection.h"
#include "relgeo/mesh/solid_validation.h"
#include "relgeo/mesh/validity.h"
#include "relgeo/subdivision.h"

namespace relgeo::test {
namespace {

using Mesh = Triangle_mesh<Point_3<double>>;
const std::string bad_dir = RELGEO_BAD_DATA_DIR;

std::string path_of(const std::string& file) { return bad_dir + "/" + file; }

/// The message without the folder of the catalogue (for the table).
std::string shown(std::string what) {
  for (std::size_t p; (p = what.find(bad_dir + "/")) != std::string::npos;) what.erase(p, bad_dir.size() + 1);
  return what;
}

/// Fragments an error message must contain (owned: a catalogue row keeps them).
using Parts = std::vector<std::string>;

void expect_mentions(const std::string& message, const Parts& parts) {
  for (const std::string& p : parts) EXPECT_NE(message.find(p), std::string::npos) << "'" << p << "' not in: " << message;
}

/// Runs f, which must throw exactly E (a relgeo::Error) mentioning `parts`,
/// quickly and without a large allocation. Returns "E: message".
template <class E, class F>
std::string expect_error(const char* name, F f, const Parts& parts) {
  const Allocation_watch watch;
  const auto start = std::chrono::steady_clock::now();
  std::string observed;
  try {
    f();
    ADD_FAILURE() << "no error";
  } catch (const E& e) {
    EXPECT_EQ(typeid(e), typeid(E)) << "a subclass was thrown: " << e.what();
    expect_mentions(e.what(), parts);
    observed = std::string(name) + " (" + std::string(to_string(e.code())) + "): " + shown(e.what());
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong error: " << e.what();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 2.0) << "bad input must fail fast";
  EXPECT_LT(watch.largest(), std::size_t{1} << 20) << "no allocation of more than 1 MB for a small bad file";
  return observed;
}

std::string read_error_unreadable(const std::string& file, const Parts& parts) {
  return expect_error<Unreadable_file>("Unreadable_file", [&] { (void)read_mesh(path_of(file)); }, parts);
}

Mesh read(const std::string& file) { return read_mesh(path_of(file)); }

/// check_mesh finds exactly these defects (count per kind).
std::string expect_defects(const Mesh_report& r, std::map<Mesh_defect, std::size_t> expected) {
  for (int d = 0; d <= static_cast<int>(Mesh_defect::undecided); ++d) {
    const auto defect = static_cast<Mesh_defect>(d);
    const std::size_t n = expected.count(defect) ? expected[defect] : 0;
    EXPECT_EQ(r.count(defect), n) << to_string(defect) << "; report: " << r.summary();
  }
  std::string s = r.summary();
  if (!r.issues.empty()) s += " (first: " + to_string(r.issues.front()) + ")";
  return s;
}

/// Loop refinement (naive double) refuses the mesh with E mentioning `parts`.
template <class E>
std::string loop_refuses(const Mesh& m, const Parts& parts) {
  return "Loop: " + expect_error<E>("Invalid_mesh/Invalid_input", [&] { (void)Loop_subdivider<Naive_kernel<double>>().refine(m, 1); }, parts);
}

std::string points_error(const std::string& file, bool parse_error, const Parts& parts) {
  if (parse_error)
    return expect_error<io::Parse_error>("Parse_error", [&] { (void)io::read_points_2(path_of(file)); }, parts);
  return expect_error<Non_finite_input>("Non_finite_input", [&] { (void)io::read_points_2(path_of(file)); }, parts);
}

struct Entry {
  const char* file;
  const char* defect;
  std::function<std::string()> check;
};

/// A mesh file every reader refuses with Unreadable_file mentioning `parts`.
Entry unreadable(const char* file, const char* defect, Parts parts) {
  return {file, defect, [file, parts] { return read_error_unreadable(file, parts); }};
}

/// A mesh file read_mesh refuses with E (named `name`) mentioning `parts`.
template <class E>
Entry refused(const char* file, const char* defect, const char* name, Parts parts) {
  return {file, defect, [file, name, parts] { return expect_error<E>(name, [file] { (void)read(file); }, parts); }};
}

/// A mesh file that reads, whose check_mesh lists `defects` and that Loop's
/// rules refuse with Invalid_mesh mentioning `loop_parts`.
Entry defective(const char* file, const char* defect, std::map<Mesh_defect, std::size_t> defects, Parts loop_parts) {
  return {file, defect, [file, defects, loop_parts] {
            const Mesh m = read(file);
            return "check_mesh: " + expect_defects(check_mesh(m), defects) + "; " +
                   loop_refuses<Invalid_mesh>(m, loop_parts);
          }};
}

/// A point file of a square (hull 4 2 0 1) at a scale outside the
/// fail-safe filter's range: exact under the filtered kernel; the fail-safe
/// one still succeeds but has no a-priori bound there.
Entry square_outside_filter_range(const char* file, const char* defect) {
  return {file, defect, [file] {
            const auto p = io::read_points_2(path_of(file));
            const std::vector<std::size_t> exact = {4, 2, 0, 1};
            EXPECT_EQ(graham_fortune<Filtered_exact_kernel>(p).indices, exact);
            const auto f = graham_fortune<Failsafe_kernel<double>>(p);
            EXPECT_TRUE(f.ok());
            EXPECT_FALSE(graham_fortune_backward_error_bound<Failsafe_kernel<double>>(p).has_value());
            return "hull (filtered): exact; failsafe: " + std::to_string(f.indices.size()) + " vertices, " +
                   std::to_string(f.uncertain_answers) +
                   " uncertain answers, a-priori bound unavailable (outside the filter's range)";
          }};
}

std::vector<Entry> catalogue() {
  return {
      // ---- empty and truncated files ----------------------------------------------
      unreadable("empty.off", "0 bytes", {"is empty"}),
      unreadable("empty.obj", "0 bytes", {"is empty"}),
      unreadable("empty.ply", "0 bytes", {"is empty"}),
      unreadable("empty.stl", "0 bytes", {"is empty"}),
      unreadable("blank_lines.off", "blank lines only", {"is empty"}),
      unreadable("truncated.off", "ends inside the faces", {"line 2", "4 faces", "lines follow"}),
      unreadable("truncated_header.off", "the face count is missing", {"line 2", "ends inside the header"}),
      unreadable("truncated.ply", "binary, ends inside the last face", {"element 'face' item 3"}),
      unreadable("truncated.stl", "binary, ends inside the last triangle", {"announces 4 triangles but holds 3"}),
      // ---- garbage ----------------------------------------------------------------------
      unreadable("garbage.obj", "no OBJ statement", {"cannot parse"}),
      unreadable("garbage.ply", "words where numbers belong", {"element 'vertex' item 0", "'zero' is not a number"}),
      unreadable("garbage.stl", "60 bytes, no 'solid'", {"60 bytes, fewer than its 84-byte header"}),
      unreadable("not_off_keyword.off", "MESH instead of OFF", {"line 1", "'MESH' is not an OFF keyword"}),
      // ---- wrong counts, huge counts --------------------------------------------------
      unreadable("wrong_counts_fewer.off", "header: 3 faces, 4 follow", {"line 10", "content after the 3 faces"}),
      unreadable("wrong_counts_more.ply", "header: 5 faces, 4 follow", {"element 'face' item 4", "ends early"}),
      unreadable("huge_face_count.off", "header: 10^7 faces, 4 follow", {"line 2", "10000000 faces", "lines follow"}),
      unreadable("huge_face_count.ply", "header: 10^7 faces, 4 follow", {"element 'face' item 4"}),
      unreadable("huge_triangle_count.stl", "header: 10^7 triangles, 4 follow", {"announces 10000000 triangles but holds 4"}),
      unreadable("huge_corner_count.off", "a face of 10^9 corners", {"line 7", "1000000000 corners"}),
      unreadable("fuzz_off_binary_huge_corner_count.off", "OFF BINARY, a face of 1.07e9 corners (found by fuzz/mesh_off)", {"face 1 announces more corners"}),
      unreadable("fuzz_ply_property_before_element.ply", "a property line before any element (found by fuzz/mesh_ply)", {"header line 4", "property before any element"}),
      unreadable("list_coordinate.ply", "a vertex coordinate declared as a list (found by fuzz/mesh_ply, reduced)", {"header line 6", "vertex coordinate 'z' declared as a list"}),
      unreadable("misread_number.ply", "'1..0', which CGAL reads as two numbers, then 2^32 - 1 read as a list count (found by fuzz/mesh_ply, reduced)", {"element 'vertex' item 0", "'1..0' is not a finite decimal number"}),
      unreadable("signed_count_overflow.ply", "a list count of 200 in a signed 8-bit type (CGAL wraps it to -56)", {"element 'face' item 0", "list count '200' is not valid"}),
      // ---- indices ----------------------------------------------------------------------
      unreadable("negative_index.off", "index -3", {"line 10", "corner 2 of face 3", "'-3'"}),
      {"index_out_of_range.off", "index 7 of 4 vertices",
       [] {
         std::string s = expect_error<Invalid_mesh>("Invalid_mesh", [] { (void)read("index_out_of_range.off"); },
                                                    {"index_out_of_range (3, 7)"});
         return s;
       }},
      refused<Invalid_mesh>("index_out_of_range.ply", "binary, index 9 of 4 vertices", "Invalid_mesh", {"index_out_of_range (3, 9)"}),
      unreadable("relative_index_out_of_range.obj", "relative index -9 of 3 vertices", {"cannot parse"}),
      refused<Invalid_input>("two_corners.obj", "a face of 2 corners", "Invalid_input", {"polygon 0 has fewer than 3 corners"}),
      // ---- NaN, infinity ----------------------------------------------------------------
      refused<Non_finite_input>("nan.off", "'nan' coordinate", "Non_finite_input", {"line 4", "vertex 1", "'nan'"}),
      refused<Non_finite_input>("inf.ply", "binary +inf coordinate", "Non_finite_input", {"vertex 1"}),
      refused<Non_finite_input>("beyond_double.off", "1e999", "Non_finite_input", {"line 4", "'1e999'"}),
      // ---- meshes that read fine: what the checks say ----------------------------------
      {"duplicated_vertex.off", "vertices 3 and 4 coincide; faces use both",
       [] {
         // Not merged: the seam through the copies is open.
         return "check_mesh: " + expect_defects(check_mesh(read("duplicated_vertex.off")), {{Mesh_defect::boundary_edge, 4}});
       }},
      {"zero_area_face.off", "vertex 3 on edge 1-2",
       [] { return "check_mesh: " + expect_defects(check_mesh(read("zero_area_face.off")), {{Mesh_defect::collinear_face, 1}}); }},
      defective("repeated_face.off", "face 0 twice", {{Mesh_defect::non_manifold_edge, 3}}, {"non_manifold_edge"}),
      defective("flipped_face.off", "face 3 reversed", {{Mesh_defect::inconsistent_orientation, 3}},
                {"inconsistent_orientation"}),
      {"inside_out.off", "every face reversed (normals inward)",
       [] {
         // check_solid checks consistent orientation, not which side is
         // outside; validate_solid's orientation test does (as CGAL's
         // is_outward_oriented, which says false).
         const Mesh m = read("inside_out.off");
         const std::string s = expect_defects(check_solid(m), {});
         const Solid_report v = validate_solid(m);
         EXPECT_EQ(v.outward_oriented.status, Check_status::fail);
         return "check_solid: " + s + " (consistent; the side is not its test); validate_solid: outward_oriented " +
                std::string(to_string(v.outward_oriented.status));
       }},
      defective("non_manifold_vertex.off", "two tetrahedra sharing vertex 0", {{Mesh_defect::non_manifold_vertex, 1}},
                {"non_manifold_vertex (0, 2)"}),
      defective("non_manifold_edge.off", "edge 1-2 in three faces",
                {{Mesh_defect::non_manifold_edge, 1}, {Mesh_defect::boundary_edge, 2}}, {"non_manifold_edge (1, 2)"}),
      {"two_faces_two_edges.off", "two faces on the same three vertices",
       [] {
         const Mesh m = read("two_faces_two_edges.off");
         return "check_mesh: " + expect_defects(check_mesh(m), {}) + "; " +
                loop_refuses<Invalid_input>(m, {"faces 0 and 1 share two edges"});
       }},
      {"open.off", "a tetrahedron without face 3",
       [] {
         const Mesh m = read("open.off");
         std::string s = "check_mesh: " + expect_defects(check_mesh(m), {{Mesh_defect::boundary_edge, 3}});
         s += "; require_valid_mesh: " + expect_error<Invalid_mesh>("Invalid_mesh", [&] { require_valid_mesh(m); },
                                                                    {"boundary_edge"});
         EXPECT_TRUE(check_mesh(m, {.require_closed = false}).is_valid());
         EXPECT_EQ(Loop_subdivider<Naive_kernel<double>>().refine(m, 1).faces.size(), 12u);
         return s + "; Loop refines it (boundary rules)";
       }},
      {"self_intersecting.off", "a second tetrahedron piercing the first",
       [] {
         const Mesh m = read("self_intersecting.off");
         EXPECT_TRUE(check_mesh(m).is_valid());
         const Mesh_report r = check_solid(m);
         EXPECT_GT(r.count(Mesh_defect::self_intersection), 0u);
         EXPECT_EQ(r.issues.size(), r.count(Mesh_defect::self_intersection));
         return "check_mesh: valid; check_solid: " + r.summary();
       }},
      // ---- extreme magnitudes ------------------------------------------------------------
      {"coordinates_1e300.off", "tetrahedron scaled by 1e300",
       [] {
         const Mesh m = read("coordinates_1e300.off");
         EXPECT_TRUE(check_solid(m).is_valid());
         const Mesh r = Loop_subdivider<Naive_kernel<double>>().refine(m, 2);
         for (const auto& p : r.vertices) EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
         // Bounds in double: |n| = |E1 x E2| ~ 1e600 overflows. Regression:
         // they used to come out NaN on 4 faces and "degenerate" on 12.
         const std::string b = expect_error<Error>(
             "Error", [&] { (void)loop_limit_mesh_bounds<Failsafe_kernel<double>>(m, 1); }, {"overflows"});
         Triangle_mesh<Point_3<mpq_class>> q;
         for (const auto& p : m.vertices) q.vertices.push_back({mpq_class(p.x), mpq_class(p.y), mpq_class(p.z)});
         q.faces = m.faces;
         const auto e = Loop_error_bounds<Exact_kernel>(Loop_options{}, {.irregular_depth = 2, .regular_depth = 1,
                                                                          .universal_depth = 2})
                            .compute(q, 1);
         for (auto d : e.degenerate) EXPECT_EQ(d, 0);
         return "check_solid: valid; Loop (double) refines 2 levels, finite; failsafe bounds: " + b +
                "; exact bounds: computed, no face degenerate";
       }},
      {"coordinates_1e-300.off", "tetrahedron scaled by 1e-300",
       [] {
         const Mesh m = read("coordinates_1e-300.off");
         EXPECT_TRUE(check_solid(m).is_valid());  // exact predicates: no underflow
         const Mesh r = Loop_subdivider<Naive_kernel<double>>().refine(m, 2);
         EXPECT_TRUE(check_mesh(r).is_valid()) << check_mesh(r).summary();
         const auto b = loop_limit_mesh_bounds<Failsafe_kernel<double>>(m, 1);
         std::size_t flagged = 0;
         for (auto d : b.degenerate) flagged += d;
         return "check_solid: valid; Loop (double) refines 2 levels, check_mesh valid; failsafe bounds: " +
                std::to_string(flagged) + " of " + std::to_string(b.limit_mesh.faces.size()) +
                " faces flagged degenerate (|n| ~ 1e-600 underflows to 0)";
       }},
      {"coordinates_max.off", "coordinates in [0.75, 1] x DBL_MAX",
       [] {
         const Mesh m = read("coordinates_max.off");
         EXPECT_TRUE(check_solid(m).is_valid());
         // Regression: refinement used to return infinite coordinates.
         std::string s = expect_error<Error>("Error",
                                             [&] { (void)Loop_subdivider<Naive_kernel<double>>().refine(m, 1); },
                                             {"overflows at vertex"});
         // Rationals hold any value: the exact kernel refines it.
         Triangle_mesh<Point_3<mpq_class>> q;
         for (const auto& p : m.vertices) q.vertices.push_back({mpq_class(p.x), mpq_class(p.y), mpq_class(p.z)});
         q.faces = m.faces;
         EXPECT_EQ(Loop_subdivider<Exact_kernel>().refine(q, 1).faces.size(), 16u);
         return "check_solid: valid; Loop (double): " + s + "; Loop (exact) refines it";
       }},
      // ---- feature tags (on tetrahedron.off) ---------------------------------------------
      {"tag_negative_index.tags", "corner -1",
       [] { return expect_error<Unreadable_file>("Unreadable_file", [] { (void)read_feature_tags(path_of("tag_negative_index.tags")); }, {"line 1", "corner -1"}); }},
      {"tag_self_edge.tags", "crease 2 2",
       [] { return expect_error<Unreadable_file>("Unreadable_file", [] { (void)read_feature_tags(path_of("tag_self_edge.tags")); }, {"line 1", "crease 2 2"}); }},
      {"tag_missing_index.tags", "crease 1",
       [] { return expect_error<Unreadable_file>("Unreadable_file", [] { (void)read_feature_tags(path_of("tag_missing_index.tags")); }, {"line 1"}); }},
      {"tag_not_an_edge.tags", "crease 0 7 on a 4-vertex mesh",
       [] {
         const Mesh m = read_mesh(path_of("tetrahedron.off"), {.tags_path = path_of("tag_not_an_edge.tags")});
         return "check_mesh: " + expect_defects(check_mesh(m), {{Mesh_defect::invalid_tag, 1}}) + "; " +
                loop_refuses<Invalid_mesh>(m, {"invalid_tag (0, 7)"});
       }},
      {"tag_corner_out_of_range.tags", "corner 99 on a 4-vertex mesh",
       [] {
         const Mesh m = read_mesh(path_of("tetrahedron.off"), {.tags_path = path_of("tag_corner_out_of_range.tags")});
         return "check_mesh: " + expect_defects(check_mesh(m), {{Mesh_defect::invalid_tag, 1}}) + "; " +
                loop_refuses<Invalid_mesh>(m, {"invalid_tag (99)"});
       }},
      // ---- point files ----------------------------------------------------------------------
      {"points_one_number.txt", "a line with one number",
       [] { return points_error("points_one_number.txt", true, {"line 2", "got 1 number"}); }},
      {"points_garbage.txt", "words",
       [] { return points_error("points_garbage.txt", true, {"line 2", "'zero' is not a number"}); }},
      {"points_nan.txt", "nan", [] { return points_error("points_nan.txt", false, {"line 2", "'nan'"}); }},
      {"points_beyond_double.txt", "1e999",
       [] { return points_error("points_beyond_double.txt", false, {"line 2", "out of the range of double"}); }},
      {"points_duplicates.txt", "repeated points",
       [] {
         const auto p = io::read_points_2(path_of("points_duplicates.txt"));
         const std::vector<std::size_t> exact = {0, 1, 5, 3};  // smallest index among equal points
         for (const auto& r : {graham_fortune<Filtered_exact_kernel>(p), monotone_chain<Filtered_exact_kernel>(p),
                               graham_incremental<Filtered_exact_kernel>(p), graham_fortune<Failsafe_kernel<double>>(p)})
           EXPECT_EQ(r.indices, exact);
         return std::string("hull (every algorithm, filtered and failsafe): 0 1 5 3, the smallest index of equal points");
       }},
      square_outside_filter_range("points_near_1e300.txt", "a square of side 2e300"),
      square_outside_filter_range("points_near_1e-300.txt", "a square of side 2e-300"),
  };
}

class Catalogue : public ::testing::TestWithParam<std::size_t> {};

TEST_P(Catalogue, DocumentedBehaviour) {
  const std::vector<Entry> all = catalogue();
  const Entry& e = all[GetParam()];
  const std::string observed = e.check();
  std::printf("CATALOGUE | %s | %s | %s\n", e.file, e.defect, observed.c_str());
}

std::string entry_name(const ::testing::TestParamInfo<std::size_t>& info) {
  std::string n = catalogue()[info.param].file;
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(BadInput, Catalogue, ::testing::Range<std::size_t>(0, catalogue().size()), entry_name);

// Every file of test/data/bad/ is in the catalogue (and every entry is a file).
TEST(BadInputCatalogue, ListsEveryFile) {
  std::vector<std::string> files;
  for (const auto& f : std::filesystem::directory_iterator(bad_dir)) {
    const std::string n = f.path().filename().string();
    if (n != "make_bad_files.py" && n != "tetrahedron.off") files.push_back(n);
  }
  std::vector<std::string> listed;
  for (const Entry& e : catalogue()) listed.push_back(e.file);
  std::sort(files.begin(), files.end());
  std::sort(listed.begin(), listed.end());
  EXPECT_EQ(files, listed);
}

}  // namespace
}  // namespace relgeo::test
