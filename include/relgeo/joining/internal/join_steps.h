// relgeo/joining/internal/join_steps.h — the steps of the joiner that need
// neither CGAL nor the Whitney extension: the options and result types,
// validation and projection of the mesh patches, joints (edge curves,
// medians, own chains), model vertices, dR of each face, central meshes.
// Shared by joiner.h and the naive sewing baseline (naive_sewing.h).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/core/floating_point.h"
#include "relgeo/core/internal/stopwatch.h"
#include "relgeo/core/internal/union_find.h"
#include "relgeo/joining/boundary_chains.h"
#include "relgeo/joining/central_mesh.h"
#include "relgeo/joining/domain_mesh.h"
#include "relgeo/joining/error_measures.h"
#include "relgeo/joining/join_report.h"
#include "relgeo/joining/joining_errors.h"
#include "relgeo/joining/projection.h"
#include "relgeo/joining/whitney_extension.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/surfaces/surface_model.h"

namespace relgeo {

/// Options of join_meshes (defaults in brackets).
struct Join_options {
  /// Use an edge's 3D curve where it has one (case 1); false: case 2
  /// everywhere (median polylines) [true].
  bool use_edge_curves = true;
  /// Spacing of the samples of an edge curve (3D); 0: the median length of
  /// the meshes' boundary edges along that edge [0].
  double curve_spacing = 0;
  Projection_options projection{};
  Central_mesh_options central{};
  /// Ruppert's shape bound [0.125] and size bound (0: the median edge length
  /// of the face's projected mesh) [0].
  Domain_mesh_options external{};
  Whitney_options whitney{};
  /// Remeshing rounds allowed until the points on shared edges agree [8].
  int max_conformity_rounds = 8;
};

/// The joined mesh, the face each triangle belongs to, the report.
struct Join_result {
  Triangle_mesh<Point_3<double>> mesh;
  std::vector<Index> face_of_triangle;
  Join_report report;
};

namespace internal::join {

/// Identity of a point on the joints: a model vertex, or position `segment`
/// + t along an edge's joint polyline.
struct Point_key {
  int vertex = -1;
  int edge = -1;
  std::uint32_t segment = 0;
  double t = 0;
  friend auto operator<=>(const Point_key&, const Point_key&) = default;
};

/// An edge of the model (or a trim curve without edge) and its joint polyline.
struct Joint {
  std::vector<Edge_use> uses;
  std::vector<Point_3<double>> points;  ///< in the edge's direction, ends at the model vertices
  int start_vertex = -1, end_vertex = -1;
  enum class Kind { curve, median, own_chain } kind = Kind::own_chain;
  std::set<std::pair<std::uint32_t, double>> extra;  ///< points added on segments (segment, t)
};

inline Point_3<double> lerp(const Point_3<double>& a, const Point_3<double>& b, double t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
}

/// A point of a face's dR.
struct Boundary_point {
  Point_2<double> uv;
  double e = 0;
  Point_key key;
};
/// Where a segment of dR lies on its edge: positions (segment + t) of its ends.
struct Segment_on_edge {
  int edge = -1;
  double from = 0, to = 0;
};

/// Everything the joiner keeps per face.
struct Face_state {
  const Trimmed_surface* face = nullptr;
  std::unique_ptr<Surface_projector> projector;
  std::vector<Point_3<double>> points;  ///< the input mesh's vertices
  std::vector<Triangle> triangles;      ///< the input mesh's faces, counter-clockwise in (u,v)
  Height_field input;                   ///< their projection
  Mesh_topology topology;
  std::vector<std::vector<Boundary_chain>> chains;  ///< [loop][curve]
  std::vector<std::vector<int>> curve_edge;         ///< [loop][curve] -> joint
  Join_face_report report;
  // dR and the meshes of the current round.
  std::vector<std::vector<Boundary_point>> boundary;
  std::vector<std::vector<Segment_on_edge>> segments;
  std::map<Point_key, std::pair<Point_2<double>, double>> projected;  ///< cache of joint points' projections
  Central_mesh central;
  std::vector<std::vector<Index>> central_cycles;
  Domain_mesh external;
  std::set<Point_key> keys_present;  ///< dR points of the current external mesh
  double median_edge_uv = 0;
};

// ---- step 1: validate and project a mesh patch ------------------------------
template <class K>
void prepare_face(Face_state& s, const Triangle_mesh<Point_3<double>>& mesh, std::size_t f, const Join_options& o,
                  const K& k) {
  const std::string name = "face " + std::to_string(f);
  if (mesh.faces.empty()) throw Joining_input_error(name + ": the mesh patch has no triangle");
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (!all_finite(mesh.vertices[v].x, mesh.vertices[v].y, mesh.vertices[v].z))
      throw Non_finite_input(name + ": mesh vertex " + std::to_string(v) + " is not finite");
  s.points = mesh.vertices;
  s.triangles = mesh.faces;
  s.topology = Mesh_topology::build(s.points.size(), s.triangles);  // Invalid_mesh for bad topology
  s.projector = std::make_unique<Surface_projector>(s.face->surface(), o.projection);
  const std::vector<Surface_projection> pr = s.projector->project_mesh(mesh);
  for (const auto& p : pr) s.input.uv.push_back(p.uv), s.input.height.push_back(p.height);
  // Orient the patch counter-clockwise in (u,v) (by the majority of its
  // certainly oriented triangles); the output follows the face's orientation.
  Orientation_report r = uv_orientations<K>(s.triangles, s.input.uv, Certified_sign::positive, k);
  if (r.flipped > r.positive) {
    for (Triangle& t : s.triangles) std::swap(t[1], t[2]);
    s.topology = Mesh_topology::build(s.points.size(), s.triangles);
    r = uv_orientations<K>(s.triangles, s.input.uv, Certified_sign::positive, k);
  }
  s.report.input_vertices = s.points.size(), s.report.input_triangles = s.triangles.size();
  s.report.orientation_before = {r.positive, r.flipped, r.degenerate, r.undecided};
  const Patch_errors before = patch_errors(s.triangles, s.input);
  s.report.before = {before.absolute_error, before.normal_vector_error};
  const auto cycles = boundary_loops(s.topology);
  if (cycles.empty()) throw Joining_input_error(name + ": the mesh patch is closed (no boundary to join)");
  s.chains = split_boundary(*s.face, cycles, s.input.uv);
  std::vector<double> lengths;
  for (const Triangle& t : s.triangles)
    for (int i = 0; i < 3; ++i)
      lengths.push_back(std::hypot(s.input.uv[t[i]].x - s.input.uv[t[(i + 1) % 3]].x,
                                   s.input.uv[t[i]].y - s.input.uv[t[(i + 1) % 3]].y));
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2), lengths.end());
  s.median_edge_uv = lengths[lengths.size() / 2];
}

/// Step 1 for every face of the model, in order.
template <class K>
std::vector<Face_state> prepare_faces(const Surface_model& model, const std::vector<Triangle_mesh<Point_3<double>>>& meshes,
                                      const Join_options& o, const K& k) {
  std::vector<Face_state> faces(model.faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    faces[f].face = &model.faces[f];
    prepare_face(faces[f], meshes[f], f, o, k);
  }
  return faces;
}

/// An empty result of `method` (by the function `who`) under the kernel named
/// `kernel`. \throws Joining_input_error unless the model has faces and there
/// is one mesh per face.
inline Join_result started_join_result(const char* who, const char* method, std::string kernel,
                                       const Surface_model& model, std::size_t number_of_meshes) {
  Join_result result;
  result.report.method = method, result.report.kernel = std::move(kernel);
  if (model.faces.empty()) throw Joining_input_error(std::string(who) + ": the model has no face");
  if (number_of_meshes != model.faces.size())
    throw Joining_input_error(std::string(who) + ": " + std::to_string(number_of_meshes) + " meshes for " +
                              std::to_string(model.faces.size()) + " faces");
  return result;
}

/// Runs f() and appends its wall time to the report under `name`.
template <class F>
void timed_step(Join_report& report, const char* name, F&& f) {
  const Stopwatch t;
  f();
  report.seconds.push_back({name, t.elapsed()});
}

// ---- step 2: joints ----------------------------------------------------------
/// Joints for the model's edges and for trim curves without one; fills
/// curve_edge of every face.
inline std::vector<Joint> make_joints(const Surface_model& model, std::vector<Face_state>& faces) {
  std::vector<Joint> joints(model.edges.size());
  const auto uses = model.edge_uses();
  for (std::size_t e = 0; e < uses.size(); ++e) joints[e].uses = uses[e];
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Trimmed_surface& face = *faces[f].face;
    faces[f].curve_edge.resize(face.inner_loops().size() + 1);
    for (std::size_t l = 0; l <= face.inner_loops().size(); ++l) {
      const Trim_loop& loop = Surface_model::loop(face, l);
      for (std::size_t c = 0; c < loop.curves.size(); ++c) {
        int e = loop.curves[c].edge;
        if (e < 0) {
          e = static_cast<int>(joints.size());
          joints.emplace_back().uses.push_back({f, l, c});
        }
        faces[f].curve_edge[l].push_back(e);
      }
    }
  }
  for (std::size_t e = 0; e < joints.size(); ++e)
    if (joints[e].uses.size() > 2)
      throw Joining_input_error("edge " + std::to_string(e) + " is shared by " + std::to_string(joints[e].uses.size()) +
                                " trim curves (at most two faces may meet along an edge)");
  return joints;
}

/// The mesh vertices of a use's chain as 3D points, in the edge's direction.
inline std::vector<Point_3<double>> chain_points(const Face_state& s, const Edge_use& u, const Surface_model&) {
  const Trim_curve& c = Surface_model::loop(*s.face, u.loop).curves[u.curve];
  std::vector<Point_3<double>> p;
  for (Index v : s.chains[u.loop][u.curve].vertices) p.push_back(s.points[v]);
  if (c.reversed) std::reverse(p.begin(), p.end());
  return p;
}

/// Model vertices, found from the topology: the end of a trim curve and the
/// start of the next one in a loop are one vertex, an end of their edges
/// (union-find over the joints' ends). Names every joint's start and end.
inline void assign_vertices(const std::vector<Face_state>& faces, std::vector<Joint>& joints) {
  Union_find<std::size_t> ends(2 * joints.size());  // 2j: start of joint j, 2j+1: its end
  for (const Face_state& s : faces)
    for (std::size_t l = 0; l < s.curve_edge.size(); ++l) {
      const Trim_loop& loop = Surface_model::loop(*s.face, l);
      const std::size_t n = loop.curves.size();
      for (std::size_t c = 0; c < n; ++c) {
        const std::size_t d = (c + 1) % n;
        // Loop end of curve c: its natural end unless reversed; loop start of d likewise.
        const std::size_t end_c = 2 * static_cast<std::size_t>(s.curve_edge[l][c]) + (loop.curves[c].reversed ? 0 : 1);
        const std::size_t start_d = 2 * static_cast<std::size_t>(s.curve_edge[l][d]) + (loop.curves[d].reversed ? 1 : 0);
        ends.unite(end_c, start_d);
      }
    }
  std::map<std::size_t, int> id;
  for (std::size_t j = 0; j < joints.size(); ++j) {
    joints[j].start_vertex = id.emplace(ends.find(2 * j), static_cast<int>(id.size())).first->second;
    joints[j].end_vertex = id.emplace(ends.find(2 * j + 1), static_cast<int>(id.size())).first->second;
  }
}

inline double median_3d_spacing(const std::vector<Point_3<double>>& p) {
  std::vector<double> l;
  for (std::size_t i = 1; i < p.size(); ++i) l.push_back(internal::distance_3(p[i], p[i - 1]));
  if (l.empty()) return 0;
  std::nth_element(l.begin(), l.begin() + static_cast<std::ptrdiff_t>(l.size() / 2), l.end());
  return l[l.size() / 2];
}

/// The joint polylines (case 1, case 2, free edges), their ends moved to the
/// model vertices' points.
inline void build_joint_polylines(const Surface_model& model, const std::vector<Face_state>& faces,
                                  std::vector<Joint>& joints, const Join_options& o, Join_report& report) {
  for (std::size_t j = 0; j < joints.size(); ++j) {
    Joint& J = joints[j];
    if (J.uses.empty()) continue;  // an edge no face of the model uses
    std::vector<std::vector<Point_3<double>>> chains;
    for (const Edge_use& u : J.uses) {
      chains.push_back(chain_points(faces[u.face], u, model));
      if (chains.back().size() < 2)
        throw Joining_input_error("face " + std::to_string(u.face) + ": the mesh patch has a single vertex along trim curve " +
                                  std::to_string(u.curve) + " of loop " + std::to_string(u.loop) + " (too coarse)");
    }
    const bool has_curve = j < model.edges.size() && model.edges[j].has_geometry();
    if (o.use_edge_curves && has_curve) {
      double spacing = o.curve_spacing;
      if (spacing <= 0) {
        std::vector<double> s;
        for (const auto& c : chains) s.push_back(median_3d_spacing(c));
        spacing = *std::min_element(s.begin(), s.end());
      }
      J.points = sample_edge(model.edges[j], spacing);
      J.kind = Joint::Kind::curve, ++report.edges_with_curve;
    } else if (chains.size() == 2) {
      J.points = median_polyline(chains[0], chains[1]);
      J.kind = Joint::Kind::median, ++report.edges_with_median;
    } else {
      J.points = chains[0];
      J.kind = Joint::Kind::own_chain, ++report.free_edges;
    }
  }
  // Model vertex points: the mean of the raw ends meeting there.
  std::map<int, std::pair<Point_3<double>, int>> sum;
  for (const Joint& J : joints)
    if (!J.uses.empty())
    for (const auto& [v, p] : {std::pair{J.start_vertex, J.points.front()}, std::pair{J.end_vertex, J.points.back()}}) {
      auto& [acc, n] = sum[v];
      acc = {acc.x + p.x, acc.y + p.y, acc.z + p.z}, ++n;
    }
  for (Joint& J : joints) {
    if (J.uses.empty()) continue;
    const auto point = [&](int v) {
      const auto& [acc, n] = sum[v];
      return Point_3<double>{acc.x / n, acc.y / n, acc.z / n};
    };
    J.points.front() = point(J.start_vertex), J.points.back() = point(J.end_vertex);
  }
}

// ---- projections of joint points onto a face --------------------------------
inline Point_3<double> key_point(const std::vector<Joint>& joints, const Point_key& key,
                                 const std::map<int, Point_3<double>>& vertex_points) {
  if (key.vertex >= 0) return vertex_points.at(key.vertex);
  const Joint& J = joints[static_cast<std::size_t>(key.edge)];
  if (key.t == 0) return J.points[key.segment];
  return lerp(J.points[key.segment], J.points[key.segment + 1], key.t);
}

inline std::pair<Point_2<double>, double> project_key(Face_state& s, const std::vector<Joint>& joints, const Point_key& key,
                                                      const std::map<int, Point_3<double>>& vertex_points,
                                                      std::optional<Point_2<double>> hint) {
  if (auto it = s.projected.find(key); it != s.projected.end()) return it->second;
  const Surface_projection p = s.projector->project(key_point(joints, key, vertex_points), hint);
  return s.projected[key] = {p.uv, p.height};
}

/// Case 2: the loops of median polylines (and of a mesh's own boundary
/// chain along a free edge) deleted in the (u,v) domains of the faces using
/// them (until simple in all), with K's certified predicates.
template <class K>
void delete_joint_loops(std::vector<Face_state>& faces, std::vector<Joint>& joints, const K& k) {
  for (Joint& J : joints) {
    if (J.kind == Joint::Kind::curve || J.uses.empty()) continue;
    for (bool changed = true; changed;) {
      changed = false;
      for (const Edge_use& u : J.uses) {
        Face_state& s = faces[u.face];
        std::vector<Point_2<double>> uv;
        std::optional<Point_2<double>> hint;
        for (const auto& p : J.points) {
          uv.push_back(s.projector->project(p, hint).uv);
          hint = uv.back();
        }
        const std::vector<std::size_t> keep = delete_loops<K>(uv, k);
        if (keep.size() == J.points.size()) continue;
        std::vector<Point_3<double>> kept;
        for (std::size_t i : keep) kept.push_back(J.points[i]);
        J.points = std::move(kept);
        changed = true;
      }
    }
  }
}

// ---- step 2 (cont.): dR of a face --------------------------------------------
/// dR of face s: each trim loop's joints in loop direction, with the extra
/// points of this round, projected onto the face.
inline void build_boundary(Face_state& s, const std::vector<Joint>& joints, const std::map<int, Point_3<double>>& vp) {
  s.boundary.clear(), s.segments.clear();
  const Trimmed_surface& face = *s.face;
  for (std::size_t l = 0; l <= face.inner_loops().size(); ++l) {
    const Trim_loop& loop = Surface_model::loop(face, l);
    std::vector<Boundary_point> pts;
    std::vector<Segment_on_edge> segs;
    std::optional<Point_2<double>> hint;
    for (std::size_t c = 0; c < loop.curves.size(); ++c) {
      const int e = s.curve_edge[l][c];
      const Joint& J = joints[static_cast<std::size_t>(e)];
      // Positions along the edge (segment, t) in the edge's direction.
      std::vector<std::pair<std::uint32_t, double>> pos;
      for (std::uint32_t i = 0; i + 1 < J.points.size(); ++i) {
        pos.push_back({i, 0.0});
        for (auto it = J.extra.lower_bound({i, 0.0}); it != J.extra.end() && it->first == i; ++it) pos.push_back(*it);
      }
      pos.push_back({static_cast<std::uint32_t>(J.points.size() - 1), 0.0});
      if (loop.curves[c].reversed) std::reverse(pos.begin(), pos.end());
      for (std::size_t i = 0; i + 1 < pos.size(); ++i) {  // the last point is the next curve's first
        Point_key key;
        const bool first = pos[i].first == 0 && pos[i].second == 0;
        const bool last = pos[i].first + 1 == J.points.size();
        if (first) key.vertex = J.start_vertex;
        else if (last) key.vertex = J.end_vertex;
        else key.edge = e, key.segment = pos[i].first, key.t = pos[i].second;
        const auto [uv, h] = project_key(s, joints, key, vp, hint);
        hint = uv;
        pts.push_back({uv, h, key});
        segs.push_back({e, pos[i].first + pos[i].second, pos[i + 1].first + pos[i + 1].second});
      }
    }
    s.boundary.push_back(std::move(pts));
    s.segments.push_back(std::move(segs));
  }
}

// ---- step 3: central mesh ------------------------------------------------------
inline std::vector<std::vector<Point_2<double>>> boundary_polygons(const Face_state& s) {
  std::vector<std::vector<Point_2<double>>> loops;
  for (const auto& l : s.boundary) {
    loops.emplace_back();
    for (const auto& p : l) loops.back().push_back(p.uv);
  }
  return loops;
}

/// The boundary cycles of the central mesh (counter-clockwise interior on the left).
inline std::vector<std::vector<Index>> central_cycles(const Face_state& s) {
  const Mesh_topology& t = s.topology;
  const auto kept_boundary = [&](Index h) {
    if (!s.central.keep[Mesh_topology::face(h)]) return false;
    const Index o = t.opposite(h);
    return o == invalid_index || !s.central.keep[Mesh_topology::face(o)];
  };
  std::vector<std::vector<Index>> cycles;
  std::vector<char> seen(t.number_of_halfedges(), 0);
  for (Index h = 0; h < t.number_of_halfedges(); ++h) {
    if (seen[h] || !kept_boundary(h)) continue;
    std::vector<Index> cycle;
    Index cur = h;
    while (!seen[cur]) {
      seen[cur] = 1;
      cycle.push_back(t.source(cur));
      Index next = invalid_index;
      t.for_each_outgoing(t.target(cur), [&](Index g) {
        if (next == invalid_index && kept_boundary(g)) next = g;
      });
      if (next == invalid_index) throw Joining_failure("central mesh: an open boundary cycle");
      cur = next;
    }
    cycles.push_back(std::move(cycle));
  }
  return cycles;
}

// ---- merging helper -----------------------------------------------------------
/// Splits triangle (a, b, c) at the points inserted on its edges (lists in
/// edge direction) into a fan per edge.
inline void split_triangle(const std::array<std::int64_t, 3>& t, const std::array<std::vector<std::int64_t>, 3>& on_edge,
                           std::vector<std::array<std::int64_t, 3>>& out) {
  int e = -1;
  for (int i = 0; i < 3; ++i)
    if (!on_edge[i].empty()) e = i;
  if (e < 0) {
    out.push_back(t);
    return;
  }
  // Fan from the corner opposite edge e: (t[e], p1, t[e+2]), ..., (pk, t[e+1], t[e+2]).
  const std::int64_t a = t[e], b = t[(e + 1) % 3], c = t[(e + 2) % 3];
  std::vector<std::int64_t> chain{a};
  chain.insert(chain.end(), on_edge[e].begin(), on_edge[e].end());
  chain.push_back(b);
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
    std::array<std::int64_t, 3> sub{chain[i], chain[i + 1], c};
    std::array<std::vector<std::int64_t>, 3> rest;
    if (i == 0) rest[2] = on_edge[(e + 2) % 3];                   // edge (c, a) of the first piece
    if (i + 2 == chain.size()) rest[1] = on_edge[(e + 1) % 3];   // edge (b, c) of the last piece
    split_triangle(sub, rest, out);
  }
}

/// The topology of a joined mesh, with its vertex and triangle counts and
/// its non-manifold edges and inconsistent orientations counted in `report`
/// (the joiner's and the sewings' measures start here).
inline Mesh_topology measured_topology(const Triangle_mesh<Point_3<double>>& m, Join_report& report) {
  report.vertices = m.vertices.size(), report.triangles = m.faces.size();
  std::vector<Mesh_issue> issues;
  Mesh_topology t = Mesh_topology::build_checked(m.vertices.size(), m.faces, issues);
  for (const Mesh_issue& i : issues) {
    report.non_manifold_edges += i.defect == Mesh_defect::non_manifold_edge;
    report.inconsistent_orientations += i.defect == Mesh_defect::inconsistent_orientation;
  }
  return t;
}

}  // namespace internal::join
}  // namespace relgeo
