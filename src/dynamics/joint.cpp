// Joint helpers shared by the world and the solver.
#include "asperity/dynamics/joint.hpp"

#include <cmath>

namespace asperity {

double distanceJointLength(const JointDesc& joint, double time) {
  // The crawling worm's muscles: length(t) = L0 + A cos(2 pi f t + phase).
  return joint.rest_length +
         joint.amplitude * std::cos(2.0 * kPi * joint.frequency * time + joint.phase);
}

}  // namespace asperity
