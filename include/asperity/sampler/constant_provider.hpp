// The simplest friction stage: every direction of every contact gets mu0 (isotropic).
#pragma once

#include "asperity/sampler/friction_provider.hpp"

namespace asperity {

class ConstantProvider : public FrictionProvider {
 public:
  std::string name() const override { return "constant"; }
  void computeCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                           const FrictionSettings& settings) override;
  // Large contact sets are filled on the pool's threads (each contact its own slot).
  void setThreadPool(const ThreadPool* pool) override { pool_ = pool; }

 private:
  const ThreadPool* pool_ = nullptr;
};

}  // namespace asperity
