// relgeo/boolean/internal/point_table.h — the Boolean's points by global
// index: A's vertices, then B's, then the intersection points.
//
// An input vertex becomes the kernel's point only when a phase reads it (the
// corners of split faces, the vertices a curve passes through): most of an
// operand is never read, and an implicit point is far larger than its three
// doubles (88 bytes under the filtered kernel, 44 MB for operands of 10^6
// faces that no phase reads). Points are kept in fixed-size chunks, so a
// reference to one stays valid while others are loaded or added.
//
// A point's approximation in doubles is kept too, once asked for: the
// triangulation of each face a point lies on asks for it (an intersection
// point on an edge lies on three faces), and so does the output, and a
// certified kernel's approximation of a point of a sliver face can take
// exact arithmetic (a quarter of a gear's Boolean, recomputed).
//
// The operands' vertices are doubles (OP = Point_3<double>), or the kernel's
// own points (OP = K::Point_3: an exact chain's earlier results).
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <utility>
#include <vector>

#include "relgeo/kernel/implicit_point.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::internal {

template <class K, class OP = Point_3<double>>
class Point_table {
 public:
  using IP = typename K::Implicit_point_3;
  using Mesh = Triangle_mesh<OP>;

  Point_table(const K& k, std::array<const Mesh*, 2> meshes)
      : meshes_(meshes),
        point_(k.construct_point_3_object()),
        implicit_(k.construct_implicit_point_3_object()),
        approximate_(k.approximate_point_3_object()),
        inputs_(meshes[0]->vertices.size() + meshes[1]->vertices.size()),
        slot_(inputs_, invalid_index) {}

  /// Global indices so far (input vertices and added points).
  Index size() const { return static_cast<Index>(slot_.size()); }
  /// The first index of an added point (A's and B's vertices come before).
  Index input_count() const { return static_cast<Index>(inputs_); }

  /// Point g; an input vertex is made the kernel's point on its first read
  /// (so this const read is not thread-safe). The reference stays valid.
  const IP& operator[](Index g) const {
    const Index s = slot_[g];
    return s != invalid_index ? row(s) : load(g);
  }
  /// K's approximation of point g (approximate_point_3_object), computed
  /// on the first request and kept (not thread-safe either).
  const Approximate_point_3& approximation(Index g) const {
    const IP& p = (*this)[g];
    Approximate_point_3& a = approximation_[slot_[g]];
    if (a.error < 0) a = approximate_(p);
    return a;
  }
  /// Frees every point (the table is empty after: size() 0).
  void clear() {
    std::vector<Index>().swap(slot_);
    std::vector<std::vector<IP>>().swap(chunks_);
    std::vector<Approximate_point_3>().swap(approximation_);
    held_ = 0;
    inputs_ = 0;
  }
  /// Adds a point; its global index.
  Index add(IP p) {
    slot_.push_back(hold(std::move(p)));
    return static_cast<Index>(slot_.size() - 1);
  }

 private:
  static constexpr std::size_t chunk_size = 1024;
  static constexpr double not_approximated = -1;  // an error no approximation has

  [[gnu::noinline]] const IP& load(Index g) const {
    const std::size_t in_a = meshes_[0]->vertices.size();
    const OP& v = g < in_a ? meshes_[0]->vertices[g] : meshes_[1]->vertices[g - in_a];
    if constexpr (std::same_as<OP, Point_3<double>>)
      slot_[g] = hold(implicit_(point_(v.x, v.y, v.z)));
    else
      slot_[g] = hold(implicit_(v));
    return row(slot_[g]);
  }
  Index hold(IP&& p) const {
    if (chunks_.empty() || chunks_.back().size() == chunk_size) {
      chunks_.emplace_back();
      chunks_.back().reserve(chunk_size);  // never grown past: no reallocation moves a point
    }
    chunks_.back().push_back(std::move(p));
    approximation_.push_back({{}, not_approximated});
    return static_cast<Index>(held_++);
  }
  const IP& row(Index s) const { return chunks_[s / chunk_size][s % chunk_size]; }

  std::array<const Mesh*, 2> meshes_;
  decltype(std::declval<const K&>().construct_point_3_object()) point_;
  decltype(std::declval<const K&>().construct_implicit_point_3_object()) implicit_;
  decltype(std::declval<const K&>().approximate_point_3_object()) approximate_;
  std::size_t inputs_;
  mutable std::vector<Index> slot_;  // global index -> held point (invalid_index: an input vertex not read yet)
  mutable std::vector<std::vector<IP>> chunks_;
  mutable std::vector<Approximate_point_3> approximation_;  // by held point; error not_approximated: not yet
  mutable std::size_t held_ = 0;
};

}  // namespace relgeo::internal
