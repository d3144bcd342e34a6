#pragma once
// The interactive planners' tunables, declared once (interaction_parameters()): authority sharing
// alpha, contact sampling (N, d), and the I-RRT's. The viewer may change them while planning
// (InteractionParameters).
//
//   Blin, Taix, Fillatreau, Fourquet, "I-RRT-C: Interactive Motion Planning with Contact", IROS
//   2016, and "Tuning Interaction in Motion Planning with Contact": authority sharing alpha,
//   contact samples N, contact distance d. Taix, Flavigne, "Motion Planning with interactive
//   devices", ECMS 2011: the I-RRT's pseudo-forces, Gaussian shooting area (sigma), sampling modes,
//   p nearest nodes.

#include <optional>
#include <string_view>

#include "tandem/collision/motion_validation.hpp"
#include "tandem/core/parameter.hpp"
#include "tandem/interaction/latest_value.hpp"
#include "tandem/space/se3_space.hpp"

namespace tandem {

/// I-RRT sampling modes (2011, section VII): around the user's position (MAG) or path (PATH), with
/// or without uniform samples added (+CS).
enum class IrrtSampling : std::uint8_t { mag, path, mag_cs, path_cs };
std::string_view to_string(IrrtSampling mode);
std::optional<IrrtSampling> parse_irrt_sampling(std::string_view name);

/// The interactive planners' tunables. The default member initialisers are the defaults every
/// surface shows; ranges, units and help are in interaction_parameters(). Lengths in scene units;
/// a value of 0 means "scaled to the scene" as documented.
struct InteractionSettings {
  /// Authority sharing: the probability that the computer has authority (a uniform sample) in an
  /// iteration; else the operator has it. 1 is BiRRT alone, 0 the operator alone. The papers' 0.5.
  double alpha = 0.5;
  /// Automatic authority sharing (AutoAlpha): alpha adapts to what each side contributes, from
  /// even shares; off, alpha stays as set (the user pins it).
  bool auto_alpha = false;
  bool contact = false;      ///< contact sampling when the operator is near an obstacle
  int contact_samples = 10;  ///< N, the papers' value
  /// d: contact mode when the object at q_device is within d of an obstacle. 0: 1.5% of the
  /// bounds' diagonal (the papers' 0.15 m in their 10 m scene).
  double contact_distance = 0.0;
  /// Gap between contact samples and the tangent plane (FCL counts touching as collision). 0:
  /// contact_clearance(s, space, validation), scaled to the space's translation step.
  double contact_clearance = 0.0;
  /// Contact on edges and corners (the 2016 paper's future work): up to this many surfaces
  /// (obstacle parts whose normals differ by 30 degrees or more) within d; with two the samples
  /// lie on the line above both tangent planes, with three at the point above all three. 1: the
  /// papers' one plane.
  int contact_surfaces = 1;
  /// Orientation change in contact: each sample turns the operator's orientation about the
  /// contact normal by up to this many degrees (uniform). 0: the papers' (the operator's own).
  double contact_turn_deg = 0.0;

  // I-RRT (2011).
  IrrtSampling sampling = IrrtSampling::mag;
  double force_mix = 0.5;  ///< the I-RRT's alpha: F_r = force_mix F_u + (1 - force_mix) F_a
  int neighbours = 10;     ///< p, nearest nodes to the user for the centre of mass (the paper's 10)
  /// sigma, standard deviation of the Gaussian shooting area across F_r, in translation; 0: 2% of
  /// the bounds' diagonal. The rotation part uses sigma / diagonal x pi.
  double sigma = 0.0;
  /// x: in +CS modes, one uniform sample every x shots when the user is still.
  int uniform_every = 10;
};

/// The declarations of InteractionSettings' fields (all live: the viewer may change them).
const ParamTable<InteractionSettings>& interaction_parameters();

/// Scene-scaled values of the "0 means default" fields.
double contact_distance(const InteractionSettings& s, const SE3Space& space);
/// 0 (the default) gives 0.1 x the translation step under discrete validation, and twice the exact
/// sweep's stop (kSweepStopSteps) under exact validation: a contact node nearer than the stop could
/// not be extended along the surface, since an exact last-valid sweep never leaves it.
double contact_clearance(const InteractionSettings& s, const SE3Space& space,
                         MotionValidation validation);
double sigma_translation(const InteractionSettings& s, const SE3Space& space);

/// InteractionSettings shared between a UI thread (which changes them) and the planner thread.
///
/// Threading: set() and current() belong to one writer thread; latest() to the planner thread, for
/// which it is wait-free (a LatestValue): the planner reads the settings at the start of each
/// iteration, so a change applies from the next iteration on.
class InteractionParameters {
 public:
  explicit InteractionParameters(const InteractionSettings& initial = {}) : current_(initial) {
    channel_.publish(initial);
  }
  void set(const InteractionSettings& s) {
    current_ = s;
    channel_.publish(s);
  }
  const InteractionSettings& current() const { return current_; }
  const InteractionSettings& latest() { return *channel_.latest(); }

 private:
  LatestValue<InteractionSettings> channel_;
  InteractionSettings current_;
};

}  // namespace tandem
