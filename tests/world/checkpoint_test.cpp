// Checkpoints (World::saveState, asperity/world/state_file.hpp): a world restored from the state
// of another after k steps, on another thread count, steps bit for bit as the saved world goes
// on, for the paper's scenes, several split points and the cpu and constant samplers; and every
// file that does not fit is refused with a message naming it.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/world/state_file.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

SceneDesc sceneOf(const std::string& name, const std::string& sampler, int threads) {
  SceneDesc desc = loadScene(test::sourcePath("scenes/" + name + ".json"));
  desc.friction_provider = sampler;
  desc.settings.threads = threads;
  return desc;
}

void steps(World& world, int n) {
  for (int k = 0; k < n; ++k) world.step();
}

struct Case {
  const char* scene;
  int total;                // steps of the uninterrupted run
  std::vector<int> splits;  // where the state is saved
};

// The uninterrupted run's hash against, for each split, a world on 2 threads loaded from the
// state of a 1-thread world (and the saver itself going on: saving changes nothing).
void expectRoundTrips(const Case& c, const std::string& sampler) {
  SCOPED_TRACE(std::string(c.scene) + " with " + sampler);
  auto whole = instantiate(sceneOf(c.scene, sampler, 1));
  steps(*whole, c.total);
  for (const int split : c.splits) {
    SCOPED_TRACE("saved after step " + std::to_string(split));
    auto saver = instantiate(sceneOf(c.scene, sampler, 1));
    steps(*saver, split);
    const std::string state = saver->saveState();
    auto loaded = instantiate(sceneOf(c.scene, sampler, 2));
    loaded->loadState(state);
    EXPECT_EQ(loaded->stepCount(), split);
    EXPECT_DOUBLE_EQ(loaded->time(), saver->time());
    steps(*loaded, c.total - split);
    steps(*saver, c.total - split);
    EXPECT_EQ(loaded->stateHash(), whole->stateHash());
    EXPECT_EQ(saver->stateHash(), whole->stateHash());
  }
}

const std::vector<Case> kCases = {
    {"stacking", 60, {0, 1, 25, 40}},
    {"boxes_on_materials", 60, {3, 30}},
    {"sawtooth_plane", 60, {10, 45}},
    {"chain_bolas_rough", 120, {7, 80}},
    {"nut_bolt", 60, {20, 41}},
    // A box on a static triangle mesh (Bullet's convex-concave pair, which clears the manifold
    // it is given) and the convex shapes' pairs (made lazily).
    {"examples/glb_asset", 60, {1, 37}},
    {"examples/shapes", 60, {15, 44}},
};

TEST(Checkpoint, RoundTripsAreBitExactWithTheCpuSampler) {
  for (const Case& c : kCases) expectRoundTrips(c, "cpu");
}

TEST(Checkpoint, RoundTripsAreBitExactWithTheConstantProvider) {
  for (const Case& c : kCases) expectRoundTrips(c, "constant");
}

// The persistence matters: the same poses and velocities without it (forgetContactHistory)
// give other bits, so the round trips above test what they claim to.
TEST(Checkpoint, PosesAloneDoNotContinueTheRun) {
  auto whole = instantiate(sceneOf("stacking", "cpu", 1));
  steps(*whole, 30);
  auto restarted = instantiate(sceneOf("stacking", "cpu", 1));
  restarted->loadState(whole->saveState());
  restarted->forgetContactHistory();
  steps(*whole, 20);
  steps(*restarted, 20);
  EXPECT_NE(restarted->stateHash(), whole->stateHash());
}

// A world that has run on is restored as well as a new one.
TEST(Checkpoint, LoadingIntoAWorldThatRanOnReplacesItsState) {
  auto saver = instantiate(sceneOf("stacking", "cpu", 1));
  steps(*saver, 20);
  const std::string state = saver->saveState();
  auto used = instantiate(sceneOf("stacking", "cpu", 1));
  steps(*used, 45);
  used->loadState(state);
  steps(*used, 15);
  steps(*saver, 15);
  EXPECT_EQ(used->stateHash(), saver->stateHash());
}

// Bytes of a file, and a file written from bytes.
std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// The message of loading `path` into a new stacking world ("" when it loads).
std::string loadError(const std::string& path, const std::string& scene = "stacking",
                      const std::string& sampler = "cpu") {
  const SceneDesc desc = sceneOf(scene, sampler, 1);
  auto world = instantiate(desc);
  try {
    loadStateFile(*world, path, sceneStateId(desc));
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

class CheckpointFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::tempDir("checkpoint");
    path_ = dir_ + "/stacking.state";
    const SceneDesc desc = sceneOf("stacking", "cpu", 1);
    auto world = instantiate(desc);
    steps(*world, 20);
    saveStateFile(*world, path_, sceneStateId(desc));
    bytes_ = readBytes(path_);
  }
  std::string variant(const std::string& name, const std::string& bytes) const {
    const std::string path = dir_ + "/" + name;
    writeBytes(path, bytes);
    return path;
  }
  std::string dir_, path_, bytes_;
};

TEST_F(CheckpointFile, AGoodFileLoadsAndNoTemporaryIsLeft) {
  EXPECT_EQ(loadError(path_), "");
  EXPECT_FALSE(std::filesystem::exists(path_ + ".tmp"));
}

TEST_F(CheckpointFile, EveryTruncationIsAnErrorNamingTheFile) {
  // Cut at every length up to the header's end, then at spread positions through the state.
  std::vector<size_t> cuts;
  for (size_t n = 0; n < 80; ++n) cuts.push_back(n);
  for (size_t n = 80; n < bytes_.size(); n += bytes_.size() / 97 + 1) cuts.push_back(n);
  for (const size_t n : cuts) {
    const std::string path = variant("cut.state", bytes_.substr(0, n));
    const std::string message = loadError(path);
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << n << ": " << message;
    if (n >= 8) {
      EXPECT_NE(message.find(n < 52 ? "truncated" : "truncated or padded"), std::string::npos)
          << message;
    }
  }
}

TEST_F(CheckpointFile, AFlippedByteIsCorrupt) {
  std::string bytes = bytes_;
  bytes[bytes.size() / 2] ^= 0x20;
  EXPECT_NE(loadError(variant("flipped.state", bytes)).find("corrupt"), std::string::npos);
}

TEST_F(CheckpointFile, AnotherFormatVersionIsNamed) {
  std::string bytes = bytes_;
  bytes[8] = static_cast<char>(kStateFormat + 1);
  EXPECT_NE(loadError(variant("v2.state", bytes)).find("state format 2, this build reads format 1"),
            std::string::npos);
}

TEST_F(CheckpointFile, AnotherSceneOrSamplerIsNamed) {
  EXPECT_NE(loadError(path_, "boxes_on_materials").find("saved from another scene"),
            std::string::npos);
  EXPECT_NE(loadError(path_, "stacking", "constant")
                .find("saved with friction provider 'cpu', this world uses 'constant'"),
            std::string::npos);
}

TEST_F(CheckpointFile, OtherFilesAreNotStates) {
  EXPECT_NE(loadError(variant("text.state", "{\"bodies\": []}\n")).find("not an Asperity state"),
            std::string::npos);
  EXPECT_NE(loadError(dir_ + "/missing.state").find("cannot be read"), std::string::npos);
}

// The file with its state's checksum recomputed after `edit`, as a forger would (FNV-1a over the
// state after the 52-byte header, stored at byte 44).
std::string reSummed(std::string bytes) {
  uint64_t hash = 1469598103934665603ull;
  for (size_t i = 52; i < bytes.size(); ++i) {
    hash ^= static_cast<unsigned char>(bytes[i]);
    hash *= 1099511628211ull;
  }
  std::memcpy(bytes.data() + 44, &hash, sizeof(hash));
  return bytes;
}

// Bullet's broadphase counters in the state: stageCurrent, then fupdates 1, dupdates 0 and
// cupdates 10, which Bullet never changes (found by that run of values, which must be unique).
size_t countersOffset(const std::string& bytes) {
  const int32_t run[] = {1, 0, 10};
  const std::string needle(reinterpret_cast<const char*>(run), sizeof(run));
  const size_t at = bytes.find(needle, 52);
  EXPECT_NE(at, std::string::npos);
  EXPECT_EQ(bytes.find(needle, at + 1), std::string::npos) << "the counters' run is not unique";
  return at - 4;
}

// Forged counters with a matching checksum: Bullet would index its stage lists with them or
// loop over them (a crash at the first step, or 2^31 passes); each is refused at load, named.
TEST_F(CheckpointFile, ForgedBroadphaseCountersAreRefusedNamingTheField) {
  const size_t at = countersOffset(bytes_);
  const std::pair<size_t, int32_t> forgeries[] = {
      {0, 100000000}, {0, -3}, {8, -1}, {8, 2147483647}, {4, -1}, {12, -5}, {32, -1}};
  const char* names[] = {"stageCurrent", "stageCurrent", "dupdates", "dupdates",
                         "fupdates",     "cupdates",     "gid"};
  for (size_t k = 0; k < std::size(forgeries); ++k) {
    std::string forged = bytes_;
    std::memcpy(forged.data() + at + forgeries[k].first, &forgeries[k].second, 4);
    const std::string error = loadError(variant("forged.state", reSummed(forged)));
    EXPECT_NE(error.find(std::string("the state's broadphase ") + names[k] + " is " +
                         std::to_string(forgeries[k].second) + ", outside"),
              std::string::npos)
        << error;
    EXPECT_EQ(error.rfind(dir_ + "/forged.state: ", 0), 0u) << error;
  }
  // The untouched counters load.
  EXPECT_EQ(loadError(variant("same.state", reSummed(bytes_))), "");
}

// A forged clock or step count (after the provider's name, "cpu"): NaN, 1e300 (at which dt no
// longer advances time) and a step count that would overflow are refused, named.
TEST_F(CheckpointFile, AForgedClockOrStepCountIsRefused) {
  const size_t clock = 52 + 8 + 3, count = clock + 8;
  const auto forged = [&](size_t at, auto value) {
    std::string bytes = bytes_;
    std::memcpy(bytes.data() + at, &value, sizeof(value));
    return loadError(variant("clock.state", reSummed(bytes)));
  };
  EXPECT_NE(forged(clock, std::nan("")).find("the state's clock is nan s"), std::string::npos);
  EXPECT_NE(forged(clock, 1e300).find("outside [0, 1e12]"), std::string::npos);
  EXPECT_NE(forged(clock, -1.0).find("the state's clock is -1"), std::string::npos);
  EXPECT_NE(forged(count, std::numeric_limits<int64_t>::max()).find("the state's step count is"),
            std::string::npos);
  EXPECT_NE(forged(count, int64_t{-2}).find("step count is -2"), std::string::npos);
}

// A device, a FIFO or a folder is refused by what it is, before a byte is read: /dev/zero
// would be read without end and a FIFO with no writer would block.
TEST_F(CheckpointFile, DevicesFifosAndFoldersAreRefusedUnread) {
  const std::string fifo = dir_ + "/pipe.state";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& path : {std::string("/dev/zero"), fifo, dir_}) {
    const std::string error = loadError(path);
    EXPECT_EQ(error.rfind(path + ": not a regular file", 0), 0u) << error;
  }
}

// A file longer than its header says is refused from the header, before its body is read.
TEST_F(CheckpointFile, AFileLongerThanItsHeaderSaysIsRefusedByItsHeader) {
  const std::string padded = variant("padded.state", bytes_ + std::string(4096, '\0'));
  EXPECT_NE(loadError(padded).find("truncated or padded"), std::string::npos);
}

TEST_F(CheckpointFile, AnUnwritablePathIsAnErrorAndLeavesTheOldFile) {
  const SceneDesc desc = sceneOf("stacking", "cpu", 1);
  auto world = instantiate(desc);
  try {
    saveStateFile(*world, "/dev/full", sceneStateId(desc));
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full: write failed"), std::string::npos) << e.what();
  }
  try {
    saveStateFile(*world, dir_ + "/no/such/dir/x.state", sceneStateId(desc));
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot open for writing"), std::string::npos) << e.what();
  }
  EXPECT_EQ(readBytes(path_), bytes_);
}

}  // namespace
}  // namespace asperity
