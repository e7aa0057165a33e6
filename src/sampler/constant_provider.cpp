// The constant friction stage: mu_d = mu0 in every direction of every contact.
#include "asperity/sampler/constant_provider.hpp"

namespace asperity {

void ConstantProvider::computeCoefficients(std::span<const Body> /*bodies*/,
                                           std::span<Contact> contacts,
                                           const FrictionSettings& settings) {
  // Isotropic: Eq. 7 with k_A = k_B = 0.
  const DirectionalMu mu =
      DirectionalMu::uniform(settings.directions, static_cast<float>(settings.mu0));
  for (Contact& c : contacts) {
    c.mu = mu;
    c.covered_pixels = 0;
    c.fallback = false;
  }
}

}  // namespace asperity
