// relgeo/subdivision/loop_weights.h — the options of Loop subdivision and the
// per-valence weights in a kernel's number type.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/number_traits.h"

namespace relgeo {

/// Which smooth-vertex weight beta(n) the refinement uses.
enum class Loop_vertex_weights {
  /// Loop (1987): beta(n) = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n; rational
  /// for n = 3, 4, 6 (3/16, 31/256, 1/16), otherwise through the number hook.
  loop,
  /// Warren (1995): beta(3) = 3/16, beta(n) = 3 / (8 n) otherwise: rational at
  /// every valence (a different limit surface, C1 as well).
  warren
};

/// Which rules apply next to creases and boundaries.
enum class Loop_crease_rules {
  /// Hoppe et al., SIGGRAPH 1994 (thesis Fig. 2.5, SPEC Sec. 4): crease and
  /// boundary edge (1/2, 1/2), crease vertex (1/8, 3/4, 1/8), corner fixed;
  /// the smooth edge rule everywhere else.
  hoppe,
  /// Biermann, Levin, Zorin, SIGGRAPH 2000: as hoppe, but a smooth edge with
  /// exactly one crease or corner endpoint v gets weight 3/4 - gamma at v and
  /// gamma at its other end (1/8 at the two opposite vertices), gamma =
  /// 1/2 - cos(theta_k) / 4, theta_k = pi / k at a crease vertex and
  /// alpha / k at a corner, k the number of faces in the sector of v that
  /// holds the edge. Gives a C1 limit at crease vertices of every sector size
  /// (subdominant eigenvalue 1/2). Only convex corners (alpha <= pi).
  biermann_levin_zorin
};

/// Options of Loop refinement and limit evaluation (designated initializers:
/// `Loop_options{.vertex_weights = Loop_vertex_weights::warren}`).
struct Loop_options {
  /// beta(n): Loop's (default) or Warren's.
  Loop_vertex_weights vertex_weights = Loop_vertex_weights::loop;
  /// Rules next to creases: Hoppe et al. 1994 (default) or Biermann-Levin-Zorin 2000.
  Loop_crease_rules crease_rules = Loop_crease_rules::hoppe;
  /// BLZ only: the sector angle alpha of every corner, as a fraction
  /// num/den of pi (default 1/2: alpha = pi/2). \pre 0 < num/den <= 1.
  long corner_angle_num = 1, corner_angle_den = 2;
};

/// \brief The weights of Loop's masks in the number type of kernel K, per
/// valence, computed once through Loop_kernel_number_traits<K> (see
/// number_traits.h for what is exact and what is approximated).
///
/// Smooth vertex of valence n: refinement (1 - n beta) v + beta sum p_i
/// (centre(n), beta(n)); limit (1 - n chi) v + chi sum p_i with
/// chi = 1 / (n + 3 / (8 beta)) = 8 beta / (3 + 8 n beta) (limit_centre(n),
/// chi(n)); this chi is the exact left eigenvector of the refinement rule for
/// whatever beta is used. cos_2pi_n(n) = cos(2 pi / n), from which the tangent
/// masks are built (loop_masks.h).
/// Accessors taking a valence require reserve(n) first (O(1) then).
template <ConstructionKernel_3 K>
class Loop_weights {
 public:
  using FT = typename K::FT;
  using Traits = Loop_kernel_number_traits<K>;

  explicit Loop_weights(const Loop_options& options = {})
      : options_(options),
        half_(Traits::rational(1, 2)), eighth_(Traits::rational(1, 8)),
        three_eighths_(Traits::rational(3, 8)), three_quarters_(Traits::rational(3, 4)),
        sixth_(Traits::rational(1, 6)), two_thirds_(Traits::rational(2, 3)),
        one_(Traits::rational(1, 1)) {
    if (options.corner_angle_den <= 0 || options.corner_angle_num <= 0 ||
        options.corner_angle_num > options.corner_angle_den)
      throw Precondition_violation("Loop_options: corner angle must be in (0, pi]");
    reserve(12);
  }

  const Loop_options& options() const { return options_; }

  /// Makes every valence up to max_valence available.
  void reserve(Index max_valence) {
    while (beta_.size() <= max_valence) add(static_cast<long>(beta_.size()));
  }
  Index max_valence() const { return static_cast<Index>(beta_.size()) - 1; }

  const FT& beta(Index n) const { return beta_[n]; }
  const FT& centre(Index n) const { return centre_[n]; }
  const FT& chi(Index n) const { return chi_[n]; }
  const FT& limit_centre(Index n) const { return limit_centre_[n]; }
  const FT& cos_2pi_n(Index n) const { return cos_[n]; }

  /// BLZ edge weight gamma for a sector of k faces at a crease vertex
  /// (theta = pi / k) or at a corner (theta = alpha / k).
  FT gamma(Index k, bool corner) const {
    const FT c = corner ? Traits::cos_2pi(options_.corner_angle_num, 2 * options_.corner_angle_den * long(k))
                        : Traits::cos_2pi(1, 2 * long(k));
    return FT(half_ - FT(Traits::rational(1, 4) * c));
  }

  const FT& half() const { return half_; }
  const FT& eighth() const { return eighth_; }
  const FT& three_eighths() const { return three_eighths_; }
  const FT& three_quarters() const { return three_quarters_; }
  const FT& sixth() const { return sixth_; }
  const FT& two_thirds() const { return two_thirds_; }
  const FT& one() const { return one_; }

 private:
  void add(long n) {
    if (n == 0) {  // valence 0 never occurs in a rule; keep the index aligned
      beta_.push_back(FT(0)), centre_.push_back(one_), chi_.push_back(FT(0)),
          limit_centre_.push_back(one_), cos_.push_back(one_);
      return;
    }
    const FT c = Traits::cos_2pi(1, n);
    FT b;
    if (options_.vertex_weights == Loop_vertex_weights::warren)
      b = n == 3 ? Traits::rational(3, 16) : Traits::rational(3, 8 * n);
    else {
      const FT t = FT(three_eighths_ + FT(Traits::rational(1, 4) * c));
      b = Traits::quotient(FT(Traits::rational(5, 8) - FT(t * t)), Traits::rational(n, 1));
    }
    const FT nn = Traits::rational(n, 1);
    const FT eight_b = FT(Traits::rational(8, 1) * b);
    const FT x = Traits::quotient(eight_b, FT(Traits::rational(3, 1) + FT(nn * eight_b)));
    beta_.push_back(b);
    centre_.push_back(FT(one_ - FT(nn * b)));
    chi_.push_back(x);
    limit_centre_.push_back(FT(one_ - FT(nn * x)));
    cos_.push_back(c);
  }

  Loop_options options_;
  FT half_, eighth_, three_eighths_, three_quarters_, sixth_, two_thirds_, one_;
  std::vector<FT> beta_, centre_, chi_, limit_centre_, cos_;
};

}  // namespace relgeo
