#include "tandem/interaction/interaction_settings.hpp"

#include "tandem/core/enum_names.hpp"

// The tables name only the fields of a ParamSpec that matter for each tunable (designated
// initializers); the others keep their defaults, which GCC's -Wextra would warn about.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace tandem {
namespace {

using S = InteractionSettings;

/// Contact beyond one plane: edges, corners and turns (the 2016 paper's future work).
void add_contact_shapes(ParamTable<S>& t) {
  t.push_back(integer_param<S>(
      {.name = "contact_surfaces",
       .label = "contact surfaces",
       .min = 1.0,
       .max = 3.0,
       .help = "Contact on edges and corners: up to this many obstacle surfaces within d (normals "
               "30 degrees apart or more); with 2 the samples lie on the line above both tangent "
               "planes, with 3 at the point above all three (1: the papers' one plane)",
       .group = "sharing",
       .live = true},
      &S::contact_surfaces));
  t.push_back(real_param<S>(
      {.name = "contact_turn",
       .label = "contact turn",
       .unit = "deg",
       .min = 0.0,
       .max = 180.0,
       .help = "Orientation change in contact: each contact sample turns the operator's "
               "orientation about the contact normal by up to this many degrees (0: the papers')",
       .group = "sharing",
       .live = true},
      &S::contact_turn_deg));
}

/// Authority sharing and contact sampling (Blin et al. 2016).
void add_sharing(ParamTable<S>& t) {
  const double inf = std::numeric_limits<double>::infinity();
  t.push_back(real_param<S>(
      {.name = "alpha",
       .symbol = "α",
       .label = "authority sharing",
       .min = 0.0,
       .max = 1.0,
       .help = "Authority sharing: the probability that the computer (a uniform sample) has "
               "authority in an iteration; else the operator has it (Blin et al. 2016, Alg. 1)",
       .group = "sharing",
       .live = true},
      &S::alpha));
  t.push_back(boolean_param<S>(
      {.name = "auto_alpha",
       .label = "automatic alpha",
       .help = "Authority sharing adapts online: the planner's work follows what each side's "
               "targets grow per query (the 2016 papers' future work); off pins alpha",
       .group = "sharing",
       .live = true},
      &S::auto_alpha));
  t.push_back(boolean_param<S>({.name = "contact",
                                .label = "contact sampling",
                                .help = "Contact sampling near obstacles (Alg. 3)",
                                .group = "sharing",
                                .live = true},
                               &S::contact));
  t.push_back(integer_param<S>(
      {.name = "contact_samples",
       .symbol = "N",
       .label = "contact samples",
       .min = 1.0,
       .max = 100000.0,
       .help = "Samples on the tangent plane each time contact mode is entered (the papers' 10)",
       .group = "sharing",
       .live = true},
      &S::contact_samples));
  t.push_back(real_param<S>(
      {.name = "contact_distance",
       .symbol = "d",
       .label = "contact distance",
       .unit = "m",
       .min = 0.0,
       .max = inf,
       .help = "Contact mode within this distance of an obstacle (0: 1.5% of the bounds' "
               "diagonal)",
       .group = "sharing",
       .live = true},
      &S::contact_distance));
  t.push_back(real_param<S>(
      {.name = "contact_clearance",
       .label = "contact clearance",
       .unit = "m",
       .min = 0.0,
       .max = inf,
       .help = "Gap between contact samples and the tangent plane (0: 0.2 x the motion "
               "checker's translation step with exact validation, 0.1 x with discrete)",
       .group = "sharing",
       .live = true},
      &S::contact_clearance));
  add_contact_shapes(t);
}

/// The I-RRT (Taix & Flavigne 2011).
void add_irrt(ParamTable<S>& t) {
  const double inf = std::numeric_limits<double>::infinity();
  t.push_back(choice_param<S>(
      {.name = "sampling",
       .label = "I-RRT sampling",
       .choices = {"mag", "path", "mag+cs", "path+cs"},
       .help = "I-RRT sampling mode: around the user (mag), around the user's path (path), with "
               "uniform samples (+cs)",
       .group = "irrt",
       .live = true},
      &S::sampling, [](IrrtSampling m) { return to_string(m); }, parse_irrt_sampling));
  t.push_back(real_param<S>(
      {.name = "sigma",
       .symbol = "σ",
       .label = "shooting area",
       .unit = "m",
       .min = 0.0,
       .max = inf,
       .help = "I-RRT: standard deviation of the Gaussian shooting area (0: 2% of the bounds' "
               "diagonal)",
       .group = "irrt",
       .live = true},
      &S::sigma));
  t.push_back(
      real_param<S>({.name = "force_mix",
                     .label = "force mix",
                     .min = 0.0,
                     .max = 1.0,
                     .help = "I-RRT: F_r = mix F_u + (1 - mix) F_a (the 2011 paper's alpha)",
                     .group = "irrt",
                     .live = true},
                    &S::force_mix));
  t.push_back(
      integer_param<S>({.name = "neighbours",
                        .symbol = "p",
                        .label = "nodes near the user",
                        .min = 1.0,
                        .max = 10000.0,
                        .help = "I-RRT: p, the nodes near the user whose centre of mass guides",
                        .group = "irrt",
                        .live = true},
                       &S::neighbours));
  t.push_back(integer_param<S>({.name = "uniform_every",
                                .symbol = "x",
                                .label = "uniform every",
                                .min = 1.0,
                                .max = 1000000.0,
                                .help = "I-RRT +cs modes: one uniform sample every x shots",
                                .group = "irrt",
                                .live = true},
                               &S::uniform_every));
}

ParamTable<S> make_table() {
  ParamTable<S> t;
  add_sharing(t);
  add_irrt(t);
  return t;
}

}  // namespace

const ParamTable<InteractionSettings>& interaction_parameters() {
  static const ParamTable<InteractionSettings> kTable = make_table();
  return kTable;
}

constexpr EnumNames<IrrtSampling, 4> kSamplingModes{{"mag", "path", "mag+cs", "path+cs"}};

std::string_view to_string(IrrtSampling mode) {
  return kSamplingModes.name(mode);
}

std::optional<IrrtSampling> parse_irrt_sampling(std::string_view name) {
  return kSamplingModes.parse(name);
}

double contact_distance(const InteractionSettings& s, const SE3Space& space) {
  return s.contact_distance > 0.0 ? s.contact_distance : 0.015 * space.translation_extent();
}
double contact_clearance(const InteractionSettings& s, const SE3Space& space,
                         MotionValidation validation) {
  if (s.contact_clearance > 0.0)
    return s.contact_clearance;
  const double steps = validation == MotionValidation::exact ? 2.0 * kSweepStopSteps : 0.1;
  return steps * space.translation_step();
}
double sigma_translation(const InteractionSettings& s, const SE3Space& space) {
  return s.sigma > 0.0 ? s.sigma : 0.02 * space.translation_extent();
}

}  // namespace tandem
