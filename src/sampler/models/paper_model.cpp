// The paper's model (Eqs. 5, 8, 7): mu_d = mu0 + k_A mean_A(d) + k_B mean_B(d), the means of
// each surface's max(0, g . d) over every pixel of P. It needs nothing of P but those sums, so
// a sampler may form them on its device (finish_sums).
#include <array>

#include "sampler/models/friction_models.hpp"

namespace asperity::models {

namespace {

void finishSums(std::span<const double> sums_a, std::span<const double> sums_b, int count,
                const ModelInputs& in, Contact& contact) {
  finishContact(contact, sums_a, sums_b, count, in.gains);
}

void reduce(const PatchFragments& f, const ModelInputs& in, Contact& contact, ModelScratch*) {
  const size_t n = in.directions.size(), count = f.pixels.size();
  std::array<std::array<double, kMaxDirections>, 2> sums{};
  for (size_t s = 0; s < 2 && count > 0; ++s) {
    accumulateDirectionalSums(std::span<const float>(f.gx[s], count),
                              std::span<const float>(f.gy[s], count), in.directions,
                              std::span<double>(sums[s].data(), n), in.simd);
  }
  finishSums(std::span<const double>(sums[0].data(), n), std::span<const double>(sums[1].data(), n),
             static_cast<int>(count), in, contact);
}

}  // namespace

const FrictionModelVariant kPaperModel{
    .kind = FrictionModel::Paper, .reduce = &reduce, .finish_sums = &finishSums};

}  // namespace asperity::models
