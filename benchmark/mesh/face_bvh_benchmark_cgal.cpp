// The CGAL subjects of relgeo_mesh_benchmark: box_intersection_d and
// box_self_intersection_d on face boxes (as CGAL's corefinement and
// self_intersections build them), AABB_tree over the faces of A with one box
// query per face of B, Polygon_mesh_processing::self_intersections over
// Epick, and Polygon_mesh_processing::volume over Epick and Epeck. With TBB
// (CGAL_LINKED_WITH_TBB) the sweeps also run with Parallel_tag in an arena of
// 2 threads.
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/box_intersection_d.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/enumerable_thread_specific.h>
#include <tbb/task_arena.h>
#endif

#include <cmath>
#include <iterator>
#include <map>
#include <type_traits>
#include <utility>
#include <vector>

#include "face_bvh_benchmark.h"
#include "relgeo/mesh/cgal_conversion.h"

namespace relgeo_bench {
namespace {

using K = CGAL::Epick;
using SM = CGAL::Surface_mesh<K::Point_3>;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, relgeo::Index,
                                                      CGAL::Box_intersection_d::ID_FROM_BOX_ADDRESS>;

std::vector<Box> face_boxes(const Mesh& m) {
  std::vector<Box> boxes;
  boxes.reserve(m.faces.size());
  for (relgeo::Index f = 0; f < m.faces.size(); ++f) {
    CGAL::Bbox_3 b;
    for (relgeo::Index v : m.faces[f]) {
      const auto& p = m.vertices[v];
      b += CGAL::Bbox_3(p.x, p.y, p.z, p.x, p.y, p.z);
    }
    boxes.emplace_back(b, f);
  }
  return boxes;
}

std::vector<const Box*> pointers(const std::vector<Box>& boxes) {
  std::vector<const Box*> p;
  p.reserve(boxes.size());
  for (const Box& b : boxes) p.push_back(&b);
  return p;
}

using Pair_list = std::vector<std::pair<relgeo::Index, relgeo::Index>>;

// What the callbacks append to: one list, or one per thread under
// Parallel_tag (CGAL calls the callback concurrently), concatenated after.
template <class Tag>
class Pair_sink {
 public:
  void add(relgeo::Index a, relgeo::Index b) {
#ifdef CGAL_LINKED_WITH_TBB
    if constexpr (std::is_same_v<Tag, CGAL::Parallel_tag>) {
      local_.local().emplace_back(a, b);
      return;
    }
#endif
    list_.emplace_back(a, b);
  }
  Pair_list take() {
#ifdef CGAL_LINKED_WITH_TBB
    if constexpr (std::is_same_v<Tag, CGAL::Parallel_tag>) {
      std::size_t n = 0;
      for (const Pair_list& l : local_) n += l.size();
      list_.reserve(n);
      for (const Pair_list& l : local_) list_.insert(list_.end(), l.begin(), l.end());
    }
#endif
    return std::move(list_);
  }

 private:
  Pair_list list_;
#ifdef CGAL_LINKED_WITH_TBB
  tbb::enumerable_thread_specific<Pair_list> local_;
#endif
};

template <class Tag>
void run_with_threads(int threads, auto&& f) {
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr (std::is_same_v<Tag, CGAL::Parallel_tag>) {
    tbb::task_arena arena(threads);
    arena.execute(f);
    return;
  }
#endif
  (void)threads;
  f();
}

template <class Tag>
void cgal_box_pairs(benchmark::State& state, const std::string& case_name) {
  const Mesh_pair_case& c = mesh_pair_case(case_name);
  std::size_t pairs = 0;
  for (auto _ : state) {
    run_with_threads<Tag>(2, [&] {
      const std::vector<Box> a = face_boxes(c.a), b = face_boxes(c.b);
      std::vector<const Box*> pa = pointers(a), pb = pointers(b);
      Pair_sink<Tag> sink;
      // CGAL's corefinement cutoff (intersection_impl.h).
      const auto cutoff = 2 * static_cast<std::ptrdiff_t>(std::sqrt(double(a.size() + b.size())));
      CGAL::box_intersection_d<Tag>(pa.begin(), pa.end(), pb.begin(), pb.end(),
                                    [&](const Box* x, const Box* y) { sink.add(x->info(), y->info()); }, cutoff);
      const Pair_list found = sink.take();
      pairs = found.size();
      benchmark::DoNotOptimize(found.data());
    });
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}

template <class Tag>
void cgal_box_self_pairs(benchmark::State& state, const std::string& case_name) {
  const Mesh& m = mesh_pair_case(case_name).a;
  std::size_t pairs = 0;
  for (auto _ : state) {
    run_with_threads<Tag>(2, [&] {
      const std::vector<Box> a = face_boxes(m);
      std::vector<const Box*> pa = pointers(a);
      Pair_sink<Tag> sink;
      // The cutoff of CGAL's self_intersections.
      CGAL::box_self_intersection_d<Tag>(pa.begin(), pa.end(),
                                         [&](const Box* x, const Box* y) { sink.add(x->info(), y->info()); },
                                         std::ptrdiff_t(2000));
      const Pair_list found = sink.take();
      pairs = found.size();
      benchmark::DoNotOptimize(found.data());
    });
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}

// AABB_tree traversal testing node boxes against the query box and each
// primitive's face box (precomputed, like the boxes of the other subjects).
struct Box_query_traits {
  const std::vector<CGAL::Bbox_3>* face_box;
  relgeo::Index query_face;
  std::vector<std::pair<relgeo::Index, relgeo::Index>>* out;
  bool go_further() const { return true; }
  template <class Primitive>
  void intersection(const CGAL::Bbox_3& q, const Primitive& p) {
    const relgeo::Index f = static_cast<relgeo::Index>(p.id().idx());
    if (CGAL::do_overlap(q, (*face_box)[f])) out->emplace_back(f, query_face);
  }
  template <class Node>
  bool do_intersect(const CGAL::Bbox_3& q, const Node& node) const {
    return CGAL::do_overlap(q, node.bbox());
  }
};

void cgal_aabb_pairs(benchmark::State& state, const std::string& case_name) {
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<SM>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
  const Mesh_pair_case& c = mesh_pair_case(case_name);
  const SM sa = relgeo::to_surface_mesh<K::Point_3>(c.a);
  std::size_t pairs = 0;
  for (auto _ : state) {
    std::vector<CGAL::Bbox_3> box_a, box_b;
    for (const Box& b : face_boxes(c.a)) box_a.push_back(b.bbox());
    for (const Box& b : face_boxes(c.b)) box_b.push_back(b.bbox());
    Tree tree(faces(sa).first, faces(sa).second, sa);
    tree.build();
    std::vector<std::pair<relgeo::Index, relgeo::Index>> found;
    Box_query_traits traits{&box_a, 0, &found};
    for (relgeo::Index f = 0; f < box_b.size(); ++f) {
      traits.query_face = f;
      if (CGAL::do_overlap(box_b[f], tree.bbox())) tree.traversal(box_b[f], traits);
    }
    pairs = found.size();
    benchmark::DoNotOptimize(found.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}

template <class Tag>
void cgal_self_intersections(benchmark::State& state, const std::string& case_name) {
  const SM sm = relgeo::to_surface_mesh<K::Point_3>(mesh_pair_case(case_name).a);
  std::size_t pairs = 0;
  for (auto _ : state) {
    run_with_threads<Tag>(2, [&] {
      std::vector<std::pair<SM::Face_index, SM::Face_index>> found;
      CGAL::Polygon_mesh_processing::self_intersections<Tag>(sm, std::back_inserter(found));
      pairs = found.size();
      benchmark::DoNotOptimize(found.data());
    });
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}

// The signed volume of mesh A; under Epeck made exact (CGAL::exact), so
// that both sides compute the exact value.
template <class Kernel>
void cgal_volume(benchmark::State& state, const std::string& case_name) {
  const auto sm = relgeo::to_surface_mesh<typename Kernel::Point_3>(mesh_pair_case(case_name).a);
  for (auto _ : state) {
    auto v = CGAL::Polygon_mesh_processing::volume(sm);
    if constexpr (std::is_same_v<Kernel, CGAL::Epeck>) CGAL::exact(v);
    benchmark::DoNotOptimize(v);
  }
}

// CGAL's polygon-soup IO on the same OFF file.
void cgal_read_off(benchmark::State& state, const std::string& case_name) {
  const std::string path = off_file(case_name);
  for (auto _ : state) {
    std::vector<K::Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    if (!CGAL::IO::read_polygon_soup(path, points, polygons)) state.SkipWithError("CGAL could not read the file");
    benchmark::DoNotOptimize(polygons.data());
  }
}

void cgal_write_off(benchmark::State& state, const std::string& case_name) {
  const Mesh& m = mesh_pair_case(case_name).a;
  std::vector<K::Point_3> points;
  for (const auto& p : m.vertices) points.emplace_back(p.x, p.y, p.z);
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& t : m.faces) polygons.push_back({t[0], t[1], t[2]});
  const std::string path = off_file(case_name) + ".cgal.off";
  for (auto _ : state)
    if (!CGAL::IO::write_polygon_soup(path, points, polygons, CGAL::parameters::stream_precision(17)))
      state.SkipWithError("CGAL could not write the file");
}

}  // namespace

void register_cgal_subjects(const std::string& kind, const std::string& c, int threads) {
  const std::string g = kind + "/" + c + "/";
  if (threads == 1) {
    if (kind == "pairs") {
      register_subject(g + "CGAL box_intersection_d", cgal_box_pairs<CGAL::Sequential_tag>, c);
      register_subject(g + "CGAL AABB_tree", cgal_aabb_pairs, c);
    } else if (kind == "self_pairs") {
      register_subject(g + "CGAL box_self_intersection_d", cgal_box_self_pairs<CGAL::Sequential_tag>, c);
    } else if (kind == "read_off") {
      register_subject(g + "CGAL IO", cgal_read_off, c);
    } else if (kind == "write_off") {
      register_subject(g + "CGAL IO", cgal_write_off, c);
    } else if (kind == "volume") {
      register_subject(g + "CGAL PMP Epick", cgal_volume<K>, c);
      if (c != "spheres-1m") register_subject(g + "CGAL PMP Epeck, exact", cgal_volume<CGAL::Epeck>, c);
    } else {
      register_subject(g + "CGAL PMP Epick", cgal_self_intersections<CGAL::Sequential_tag>, c);
    }
    return;
  }
#ifdef CGAL_LINKED_WITH_TBB
  if (kind == "pairs") register_subject(g + "CGAL box_intersection_d 2 threads", cgal_box_pairs<CGAL::Parallel_tag>, c);
  else if (kind == "self_pairs")
    register_subject(g + "CGAL box_self_intersection_d 2 threads", cgal_box_self_pairs<CGAL::Parallel_tag>, c);
  else register_subject(g + "CGAL PMP Epick 2 threads", cgal_self_intersections<CGAL::Parallel_tag>, c);
#endif
}

}  // namespace relgeo_bench
