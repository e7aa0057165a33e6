// The constraint solver: projected Gauss-Seidel (sequential impulses) on body velocities, for
// contacts (normal row + 2D friction block projected on a limit surface, SPEC 4) and joints.
//
// Rows act on A with the contact conventions of collision/contact.hpp. Per iteration, in a
// fixed order: joint rows, then each contact's normal row (lambda_n >= 0), its tangential
// block (the unconstrained 2x2 update, then the accumulated (lambda_t, lambda_b) projected
// on the limit surface for the CURRENT lambda_n; when that update lands outside, i.e. the
// contact slides, the update is redone with the isotropic step 1 / k_max so the friction
// opposes the slip), and its split-impulse position row.
// Position errors of contacts are removed by split impulses: pseudo-velocities that move the
// bodies but are forgotten after the step, so stabilisation adds no kinetic energy. Ball joints
// remove drift the same way; hinge, fixed and distance rows use a Baumgarte velocity bias.
// Cost per iteration is linear in the number of rows; nothing is
// allocated in the iteration loop; the projection is picked once per solve, not per row.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

#include "asperity/collision/contact.hpp"
#include "asperity/dynamics/body.hpp"
#include "asperity/dynamics/joint.hpp"
#include "asperity/friction/limit_surface.hpp"
#include "asperity/math/state_stream.hpp"
#include "asperity/math/types.hpp"
#include "math/lanes.hpp"

namespace asperity {

class ThreadPool;

struct SolverSettings {
  double dt = 0.01;  // s
  LimitSurfaceKind limit_surface = LimitSurfaceKind::Box;
  double coulomb_mu = 0.2;            // mu0 of the isotropic Coulomb limit (SPEC 4)
  double baumgarte = 0.2;             // fraction of a position error removed per step
  double slop = 0.0;                  // m of penetration left uncorrected
  double max_correction_speed = 2.0;  // m/s
  bool warm_starting = true;
};

// A joint as the solver sees it: anchors and axes in the bodies' centre-of-mass frames.
struct SolverJoint {
  JointType type = JointType::Ball;
  BodyId body_a = kNoBody;
  BodyId body_b = kNoBody;
  Vec3 anchor_a = Vec3::Zero();
  Vec3 anchor_b = Vec3::Zero();
  Vec3 axis_a = Vec3::UnitZ();
  Vec3 axis_b = Vec3::UnitZ();
  Quat rest_rotation = Quat::Identity();  // fixed: q_a^-1 q_b wanted
  double length = 0.0;                    // distance: target length at the end of the step (m)
  double length_rate = 0.0;               // distance: d length / dt (m/s)
};

class ContactSolver {
 public:
  // The threads of the calls below (null: the calling thread only). Per-body and per-contact
  // work writes only its own slots and islands share no moving body, so the results are the
  // same bits on any thread count.
  void setThreadPool(const ThreadPool* pool) { pool_ = pool; }
  // Copies body velocities (after external forces) and inverse masses; clears the rows.
  void begin(std::span<const Body> bodies, const SolverSettings& settings);
  // Joint rows (anchors in world from the bodies' poses).
  void setJoints(std::span<const SolverJoint> joints);
  // Joint rows from the joints' descriptions (bodies as given to begin): anchors and axes
  // moved from the descriptions' body frames to the centre-of-mass frames, a distance joint's
  // length at time t and its rate over dt; rest_rotations[i] is joint i's q_a^-1 q_b at
  // creation (fixed joints).
  void setJoints(std::span<const JointDesc> joints, std::span<const Quat> rest_rotations, double t,
                 double dt);
  // Contact rows, in the parts of the solve stage (solver/solve_stage.hpp). setContactRows
  // reads only the contacts' geometry and frames, so the rows can be built while the
  // coefficients are still being computed (on a GPU); without friction only the normal rows
  // are solved (frame mode Auto's prediction). setContactLimits, with the same contacts now
  // carrying mu, adds the limit surfaces; warmStart builds the islands and applies the last
  // step's impulses (contacts and joints). The sweep order is chosen on the calling thread;
  // rows, limit surfaces and warm starts are written straight into their slots in that order,
  // on the pool.
  void setContactRows(std::span<const Contact> contacts, bool friction);
  void setContactLimits(std::span<const Contact> contacts);
  void warmStart(std::span<const Contact> contacts);
  // The three above in one call.
  void setContacts(std::span<const Contact> contacts, bool friction);
  // `iterations` PGS sweeps. The rows fall into islands that share no moving body; each
  // island is swept on its own (on the pool's threads), its rows in the global sweep order,
  // which gives exactly the bits of one sweep over all rows: rows of other islands never read
  // its bodies.
  void iterate(int iterations);
  // Writes velocities and impulses back and remembers them for the next step's warm start.
  void finish(std::span<Body> bodies, std::span<Contact> contacts);

  // Each contact's normal impulse of the last step, as its warm start finds it (0 for a new
  // contact), into its lambda_n before this step's friction: the load of the contact-area
  // friction model (docs/contact-area.md). The solve overwrites it.
  void previousNormalImpulses(std::span<Contact> contacts) const;
  // Forgets the impulses kept for warm starting (contacts and joints), as in a new solver.
  void forgetWarmStart();
  // The kept impulses (contacts by key, joints), saved and restored bit for bit
  // (World::saveState): a restored solver warm-starts exactly as the saved one would have.
  void saveWarmStart(StateWriter& out) const;
  void loadWarmStart(StateReader& in);
  // The pool of setThreadPool (null: the calling thread only).
  const ThreadPool* threadPool() const { return pool_; }
  // Current solver velocities of a body (world frame), and of all bodies by BodyId.
  const Vec3& linearVelocity(BodyId id) const { return v_[id]; }
  const Vec3& angularVelocity(BodyId id) const { return w_[id]; }
  // Position-correction pseudo-velocities of the last solve (applied by integration only).
  const Vec3& pseudoLinear(BodyId id) const { return vp_[id]; }
  const Vec3& pseudoAngular(BodyId id) const { return wp_[id]; }
  std::span<const Vec3> linearVelocities() const { return v_; }
  std::span<const Vec3> angularVelocities() const { return w_; }
  std::span<const Vec3> pseudoLinearVelocities() const { return vp_; }
  std::span<const Vec3> pseudoAngularVelocities() const { return wp_; }
  // Norm of the impulse changes of the last sweep (N s): falls as the solve converges.
  double lastDelta() const { return last_delta_; }
  int contactRowCount() const { return static_cast<int>(rows_.size()); }
  // Fewest rows (contacts and joint rows) that the islands are swept in parallel for, and
  // fewest items (bodies, contacts) that per-item work goes to the threads for: below that,
  // waking them costs more than the work.
  static constexpr size_t kParallelRows = 256;

  // One contact: Jacobians, I^-1 J^T, effective masses and accumulated impulses. Every field
  // is written by prepareContact, so a new row starts uninitialised (see RowAllocator).
  struct ContactRow {
    int a, b;
    Vec3 n, t;                                // normal and tangent t (world); b = n x t
    Vec3 ra, rb;                              // contact point from each centre of mass
    Vec3 ia_n, ib_n, ia_t, ib_t, ia_b, ib_b;  // I^-1 (r x direction)
    double mass_n;                            // 1 / K_nn
    Vec3 inv_k;          // inverse of the tangential 2x2 block K: (K^-1_tt, K^-1_tb, K^-1_bb)
    double inv_k_slide;  // 1 / largest eigenvalue of that block
    double k_tn, k_bn;   // K_tn, K_bn: tangential response to lambda_n
    double target_n;     // normal velocity target (negative for separated contacts)
    double target_p;     // pseudo-velocity target of the split impulse
    double lambda_n, lambda_t, lambda_b, lambda_p;
  };
  // Grows a vector by default-initialised elements (none of a row's bytes written), where
  // std::allocator would zero them: the rows of a step are made anew, a megabyte for a pile of
  // a thousand cubes, and that pass would run on one thread.
  template <class T>
  struct RowAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
      using other = RowAllocator<U>;
    };
    RowAllocator() = default;
    template <class U>
    RowAllocator(const RowAllocator<U>& /*other*/) noexcept {}
    template <class U>
    void construct(U* p) noexcept {
      ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
      ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
  };
  using Rows = std::vector<ContactRow, RowAllocator<ContactRow>>;
  // A point-to-point (ball) block of three rows.
  struct BallRow {
    int a = 0, b = 0, joint = 0;
    Vec3 ra, rb;  // anchors relative to the centres of mass (world)
    Mat3 inv_k;   // inverse effective mass
    Vec3 bias;    // Baumgarte velocity bias
    Vec3 lambda = Vec3::Zero();
  };
  // One scalar row: J v = lin.(v_a - v_b) + ang_a.w_a - ang_b.w_b, unbounded.
  struct AxisRow {
    int a = 0, b = 0, joint = 0, slot = 0;
    // Jacobian and I^-1 of its angular parts.
    Vec3 lin = Vec3::Zero(), ang_a = Vec3::Zero(), ang_b = Vec3::Zero();
    Vec3 ia = Vec3::Zero(), ib = Vec3::Zero();
    double mass = 0.0, target = 0.0, lambda = 0.0;
  };

  // One vector of limit surfaces per solve, of the type the settings name (LimitSurfaceTypes).
  template <class Types>
  struct VectorsOf;
  template <class... Limit>
  struct VectorsOf<std::tuple<Limit...>> {
    using type = std::variant<std::vector<Limit>...>;
  };
  using LimitVectors = VectorsOf<LimitSurfaceTypes>::type;

 private:
  struct Cached {
    BodyId a, b;
    uint64_t key;
    double lambda_n;
    Vec3 tangential;                        // lambda_t t + lambda_b b, world frame
    bool operator<(const Cached& o) const;  // by (a, b, key)
  };

  void prepareContact(const Contact& c, ContactRow& row) const;
  void makeLimit(const Contact& contact, size_t row);
  // The parts of setContacts: the sweep order and room for the rows (and, with friction, their
  // limit surfaces); then, per contact into its slot, its row, its limit surface and its warm
  // start, as asked.
  void placeRows(std::span<const Contact> contacts, bool friction);
  void fillRows(std::span<const Contact> contacts, bool rows, bool limits, bool warm);
  void scheduleRows(std::span<const Contact> contacts);
  const Cached* findCached(const Contact& c, size_t& cursor) const;
  void warmStartRow(const Cached& cached, ContactRow& row, size_t slot) const;
  void warmStartJoints();
  void addAngularRow(int a, int b, int joint, int slot, const Vec3& u, double target);
  void addAxisRow(AxisRow row);
  void storeJointImpulses();
  // Rows (indices into balls_, axes_, rows_, ascending) that touch one group of moving bodies.
  struct Island {
    std::vector<int> balls, axes, contacts;
    std::vector<int> warm;  // its contact rows in contact order (warmStart)
  };
  void buildIslands();
  // body(k) for every island k, on the pool when there is enough work.
  void forEachIsland(const std::function<void(size_t)>& body) const;
  // The pool for `tasks` islands or pairs of islands, or null when one thread does better.
  const ThreadPool* islandPool(size_t tasks) const;
  int findRoot(int body);
  // `iterations` sweeps of two islands side by side; delta_* get each one's last squared
  // impulse change.
  void sweepIslands(const Island& x, const Island& y, int iterations, double& delta_x,
                    double& delta_y);
  template <class Limit>
  void sweepContacts(std::span<const Limit> limits, std::span<const int> x, std::span<const int> y,
                     double& delta_x, double& delta_y);
  // One contact row's normal and tangential update (and its position row), and the same for
  // two rows of different islands in the two lanes of a register.
  template <class Limit>
  void sweepRow(std::span<const Limit> limits, size_t i, double& delta2);
  template <class Limit>
  void sweepRowPair(std::span<const Limit> limits, size_t ix, size_t iy, lanes::Lanes& delta2);
  // The new velocities of the two rows' bodies (lanes: the rows), stored for moving bodies.
  void storePair(const size_t a[2], const size_t b[2], lanes::Lanes ima, lanes::Lanes imb,
                 const lanes::Lanes3& va, const lanes::Lanes3& wa, const lanes::Lanes3& vb,
                 const lanes::Lanes3& wb);
  void solvePositionRow(ContactRow& r, size_t a, size_t b);
  double sweepJoints(const Island& island);
  void applyImpulse(int a, int b, const Vec3& p, const Vec3& ia, const Vec3& ib);

  SolverSettings settings_;
  const ThreadPool* pool_ = nullptr;
  // Per body (indexed by BodyId): velocities, pseudo-velocities, inverse masses.
  std::vector<Vec3> v_, w_, vp_, wp_;
  std::vector<double> inv_mass_;
  std::vector<Mat3> inv_inertia_;
  std::vector<Vec3> position_;
  std::vector<Quat> rotation_;
  // Rows.
  Rows rows_;
  std::vector<int> order_;    // sweep order of the contact rows (see scheduleRows)
  std::vector<int> pending_;  // scratch of scheduleRows
  std::vector<int> slot_;     // contact i's row in rows_ (rows_ is stored in sweep order)
  LimitVectors limits_;       // one per contact row, of the settings' limit surface
  bool friction_ = true;
  bool islands_ready_ = false;  // islands_ match the rows (buildIslands since the last change)
  std::vector<BallRow> balls_;
  std::vector<AxisRow> axes_;
  std::vector<double> joint_lambda_;   // 6 slots per joint, kept for the next warm start
  std::vector<SolverJoint> joints_;    // scratch of setJoints from descriptions
  std::vector<Transform> com_offset_;  // per body: Body::com_offset (begin)
  // Islands of this solve, reused across steps (only the first island_count_ are live).
  std::vector<Island> islands_;
  size_t island_count_ = 0;
  std::vector<int> root_;        // union-find over bodies
  std::vector<int> island_of_;   // island of a root body, -1 before it has one
  std::vector<int> row_island_;  // island of each contact row
  std::vector<double> island_delta_;
  // Warm-start cache of the previous step, sorted by key.
  std::vector<Cached> cache_;
  double last_delta_ = 0.0;
};

}  // namespace asperity
