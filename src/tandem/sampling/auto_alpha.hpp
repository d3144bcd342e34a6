#pragma once
// Automatic authority sharing: the 2016 papers' future work ("adapt the authority sharing alpha
// automatically"), with no parameter for the user to tune.
//
// Each iteration is either the computer's (a uniform sample) or the operator's (q_device, or
// contact samples around it). The planner credits each of an iteration's targets with what its
// extension and the other tree's connection toward the new node did: the length of motion they
// added to the trees, and the collision queries they cost (RRTConnect::credit). The length is the
// trees' growth into space they did not cover: a target in a region the tree already fills (a
// uniform sample in a saturated room, a hand that stays put) is reached by a short motion or by
// none, a trapped one adds nothing, while a target beyond the frontier (the hand entering a
// passage, samples in an open region) adds a whole step, and a connection the whole way it went.
// AutoAlpha keeps, for each side, exponential means of an iteration's growth and of its cost over
// about kMemory of that side's iterations, so each side's recent growth per query, and shares the
// planner's work by probability matching:
//   w = (computer + prior) / (computer + operator + 2 prior), kept within [kFloor, 1 - kFloor]
// is the computer's share of the queries (the floor keeps each side tried, its rate current),
// and alpha is the share of the iterations that gives it, their costs being unequal (an
// operator's iteration in contact mode, N samples, costs about N of the computer's; an idle
// hand's, nearly nothing):
//   alpha = w c_o / (w c_o + (1 - w) c_c),  c_c and c_o the mean queries of an iteration.
//
// What it does: where uniform samples grow the trees for fewer queries than the person's hand (an
// open scene, a maze the hand walks slowly), alpha rises toward the computer; where the random
// trees fill their regions and the operator's way goes on, it falls toward the operator. Before
// anything is learnt the shares are even. Deterministic (a function of the credits).
//
// Threading: the planner thread only.

#include <algorithm>

namespace tandem {

class AutoAlpha {
 public:
  static constexpr double kMemory = 1000.0;  ///< iterations of a side that its means remember
  static constexpr double kFloor = 0.1;      ///< each side's least share of the queries

  /// `prior`: the growth per query that counts as none (scene units, e.g. 1e-9 of the space's
  /// largest extent); it keeps even shares before anything is learnt.
  explicit AutoAlpha(double prior) : prior_(prior) {}

  /// One iteration ended: whose it was, the length the trees grew (>= 0) and the queries it cost.
  void record(bool computer, double progress, double queries) {
    Side& side = sides_[computer ? 0 : 1];
    side.progress += (progress - side.progress) / kMemory;
    side.queries += (queries - side.queries) / kMemory;
  }

  /// The computer's share of the planner's queries that the recent growth calls for.
  double work_share() const {
    const double c = computer_rate(), o = operator_rate();
    return std::clamp((c + prior_) / (c + o + 2.0 * prior_), kFloor, 1.0 - kFloor);
  }

  /// The probability that the computer has authority in the next iteration.
  double alpha() const {
    const double w = work_share();
    const double c_c = sides_[0].queries, c_o = sides_[1].queries;
    if (c_c <= 0.0 || c_o <= 0.0)
      return w;  // a side's cost is not known yet
    return w * c_o / (w * c_o + (1.0 - w) * c_c);
  }

  /// Recent growth per query of the computer's and of the operator's iterations.
  double computer_rate() const { return sides_[0].rate(); }
  double operator_rate() const { return sides_[1].rate(); }

 private:
  struct Side {
    double progress = 0.0;  ///< exponential mean of an iteration's growth
    double queries = 0.0;   ///< and of its queries
    double rate() const { return queries > 0.0 ? progress / queries : 0.0; }
  };
  double prior_;
  Side sides_[2];
};

}  // namespace tandem
