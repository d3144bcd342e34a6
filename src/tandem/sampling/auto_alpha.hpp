#pragma once
// Automatic authority sharing: the 2016 papers' future work ("adapt the authority sharing alpha
// automatically"), with no parameter for the user to tune.
//
// Each iteration is either the computer's (a uniform sample) or the operator's (q_device, or
// contact samples around it). The planner credits every extension toward an iteration's targets,
// and the other tree's connection toward the node it added, with the progress it made: how much
// nearer the tree it grew came to the other tree's root than that tree had ever come
// (RRTConnect::credit; 0 for a trapped extension). AutoAlpha keeps, for
// each side, the progress per extension of its recent iterations (exponential means of progress
// and of extensions over about kMemory of that side's iterations: an operator's iteration in
// contact mode, N extensions, costs N times a random one and is weighed so) and gives the
// computer authority in proportion to its share of that rate (probability matching):
// alpha = (computer + prior) / (computer + operator + 2 prior), kept within [kFloor, 1 - kFloor]
// so that each side keeps being tried and its rate stays current.
//
// What it does: where uniform samples carry the trees toward each other faster than a person's
// hand (an open scene), alpha rises toward the computer; where the random trees stall before a
// narrow passage and the operator's way goes on, it falls toward the operator; when neither makes
// progress it drifts back toward even shares. Deterministic (a function of the credits).
//
// Threading: the planner thread only.

namespace tandem {

class AutoAlpha {
 public:
  static constexpr double kMemory = 1000.0;  ///< iterations of a side that its mean remembers
  static constexpr double kFloor = 0.1;      ///< each side's least share of the iterations

  /// `prior`: the progress per extension that counts as none (scene units, e.g. 1e-6 of the
  /// space's largest extent); it keeps alpha at even shares before anything is learnt.
  explicit AutoAlpha(double prior) : prior_(prior) {}

  /// One iteration ended: whose it was, the progress its extensions made (>= 0) and how many
  /// there were.
  void record(bool computer, double progress, int extensions) {
    Side& side = sides_[computer ? 0 : 1];
    side.progress += (progress - side.progress) / kMemory;
    side.extensions += (extensions - side.extensions) / kMemory;
  }

  /// The probability that the computer has authority in the next iteration.
  double alpha() const {
    const double c = computer_rate(), o = operator_rate();
    const double a = (c + prior_) / (c + o + 2.0 * prior_);
    return a < kFloor ? kFloor : (a > 1.0 - kFloor ? 1.0 - kFloor : a);
  }

  /// Recent progress per extension of the computer's and of the operator's iterations.
  double computer_rate() const { return sides_[0].rate(); }
  double operator_rate() const { return sides_[1].rate(); }

 private:
  struct Side {
    double progress = 0.0;    ///< exponential mean of an iteration's progress
    double extensions = 0.0;  ///< and of its extensions
    double rate() const { return extensions > 0.0 ? progress / extensions : 0.0; }
  };
  double prior_;
  Side sides_[2];
};

}  // namespace tandem
