#pragma once
// The I-RRT's shooting area (Taix and Flavigne 2011, section V-B): "a Gaussian (elliptic) shooting
// area centered on the user's position and oriented along the force direction".
//
// A displacement z is drawn from a normal distribution in the 6-D tangent space (translation with
// standard deviation sigma_t, rotation vector with sigma_r), then stretched along F_r: in units of
// the deviations, u = F_r / |F_r| and z' = z + (k - 1) (u . z) u with k = 1 + |F_r| (|F_r| also in
// units of the deviations), so the area is elongated along F_r in proportion to its strength. The
// sample is the centre moved by z' (translation added, rotation vector applied in the world frame),
// kept inside the bounds. In a planar space only x, y and the rotation about z are drawn.

#include "tandem/core/rng.hpp"
#include "tandem/interaction/operator_state.hpp"
#include "tandem/space/se3_space.hpp"

namespace tandem {

Config gaussian_shot(const SE3Space& space, const Config& centre, const Twist& force,
                     double sigma_t, double sigma_r, Rng& rng);

/// The displacement from a to b in the tangent space: translation difference and the rotation
/// vector of b a^-1 (shorter way).
Twist tangent_difference(const Config& a, const Config& b);

}  // namespace tandem
