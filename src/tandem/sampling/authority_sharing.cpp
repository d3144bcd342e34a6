#include "tandem/sampling/authority_sharing.hpp"

#include <numbers>
#include <stdexcept>

#include "tandem/sampling/contact_sampler.hpp"

namespace tandem {
namespace {

/// Growth per collision query that counts as none, as a share of the space's largest extent.
constexpr double kNoProgress = 1e-9;

}  // namespace

AuthoritySharing::AuthoritySharing(const SE3Space& space, const Interaction& interaction,
                                   const InteractionSettings& settings, std::uint64_t seed,
                                   MotionValidation validation, CollisionChecker* checker)
    : space_(space),
      validation_(validation),
      checker_(checker),
      interaction_(interaction),
      settings_(settings),
      authority_rng_(seed ^ 0xa5a5a5a5deadbeefULL),
      contact_rng_(seed ^ 0x5a5a5a5a12345678ULL),
      auto_alpha_(kNoProgress * space.max_extent()) {
  if (interaction.feed == nullptr)
    throw std::invalid_argument("authority sharing needs an operator (an OperatorFeed)");
}

void AuthoritySharing::sample(const SampleRequest& request, std::vector<Target>& out) {
  const InteractionSettings& s =
      interaction_.parameters != nullptr ? interaction_.parameters->latest() : settings_;
  // Steps 1-2: the operator has authority when a > alpha.
  const double alpha = authority_share(s);
  in_turn_ = true;
  computer_turn_ = true;
  if (authority_rng_.uniform01() > alpha) {
    const OperatorState* op = interaction_.feed->at(request.iteration, request.roadmap);
    if (op != nullptr) {
      computer_turn_ = false;
      ++stats_.operator_iterations;
      if (contact_sampling(*op, s, out))
        return;
      // Step 9.
      out.push_back({op->device.q_device, NodeSource::operator_});
      return;
    }
  }
  // Step 3.
  out.push_back({space_.sample_uniform(*request.rng), NodeSource::random});
}

bool AuthoritySharing::contact_sampling(const OperatorState& op, const InteractionSettings& s,
                                        std::vector<Target>& out) {
  const auto& frame = op.frame;
  const double d = contact_distance(s, space_);
  if (!s.contact || !frame || frame->distance > d)
    return false;
  // Step 7: ContactSampling(P_o, P_n, N, q_device).
  ++stats_.contact_entries;
  const double clearance = contact_clearance(s, space_, validation_);
  const std::size_t before = out.size();
  // With the defaults (one surface, no turn), the papers' one plane and the operator's orientation.
  const std::vector<ContactFrame> frames = contact_surfaces(op, s, d);
  const double turn = s.contact_turn_deg * std::numbers::pi / 180.0;
  for (int i = 0; i < s.contact_samples; ++i) {
    if (auto q = sample_contact_surfaces(frames, op.device.q_device.q, space_, clearance, turn,
                                         contact_rng_))
      out.push_back({*q, NodeSource::contact});
  }
  return out.size() > before;
}

std::vector<ContactFrame> AuthoritySharing::contact_surfaces(const OperatorState& op,
                                                             const InteractionSettings& s,
                                                             double d) {
  std::vector<ContactFrame> frames{*op.frame};
  if (s.contact_surfaces <= 1 || checker_ == nullptr)
    return frames;
  for (const NearestObstacle& near : checker_->nearest_surfaces(op.device.q_device, d)) {
    if (auto f = find_local_frame(near, op.device.q_device))
      frames.push_back(*f);
  }
  return distinct_surfaces(frames, static_cast<std::size_t>(s.contact_surfaces));
}

double AuthoritySharing::authority_share(const InteractionSettings& s) {
  if (in_turn_)
    auto_alpha_.record(computer_turn_, turn_progress_, static_cast<double>(turn_queries_));
  turn_progress_ = 0.0;
  turn_queries_ = 0;
  stats_.alpha = s.auto_alpha ? auto_alpha_.alpha() : s.alpha;
  return stats_.alpha;
}

void AuthoritySharing::credit(NodeSource /*source*/, double progress, std::uint64_t queries) {
  turn_progress_ += progress;
  // A target costs a nearest-neighbour search even when it needs no query (a node already): one
  // unit, so that an idle hand's iterations are not free.
  turn_queries_ += queries + 1;
}

SamplerStats AuthoritySharing::stats() const {
  SamplerStats s = stats_;
  s.operator_time_s = interaction_.feed->operator_seconds();
  return s;
}

}  // namespace tandem
