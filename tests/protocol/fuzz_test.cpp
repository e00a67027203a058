// Random and mutated frames: decode either refuses them with ProtocolError or returns a
// message that encodes back to exactly the same bytes. Nothing else may happen (this runs
// under AddressSanitizer and UBSan in the debug preset).
#include <bit>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>
#include <random>

#include <gtest/gtest.h>

#include "coupler/protocol/layout.hpp"
#include "tests/protocol/wire.hpp"

namespace cosim::protocol {
namespace {

namespace L = layout;
using testing::Frame;
using testing::Frames;
using testing::poke;

// Each base message gives itself, one random message and its mutants: 200k cases.
constexpr int kBases = 25000;
constexpr int kMutantsPerBase = 6;

class Fuzzer {
 public:
  explicit Fuzzer(std::uint64_t seed) : rng_(seed) {}

  Message valid_message() {
    Message m;
    m.header.type = static_cast<Type>(between(1, 13));
    m.header.participant = name();
    m.header.window = rng_();
    m.header.iteration = static_cast<std::uint32_t>(rng_());
    m.header.provides = static_cast<std::uint32_t>(rng_());
    m.header.needs = static_cast<std::uint32_t>(rng_());
    m.header.ranks = static_cast<std::uint32_t>(between(1, 1024));
    m.header.t0 = std::uniform_real_distribution<double>(-1e6, 1e6)(rng_);
    m.header.t1 = m.header.t0 + std::uniform_real_distribution<double>(0, 10)(rng_);
    const int n = between(0, 5);
    for (int i = 0; i < n; ++i) m.arrays.push_back(array());
    return m;
  }

  Frames random_frames() {
    Frames f(between(0, 4));
    for (Frame& frame : f) frame = bytes(between(0, 120));
    if (!f.empty() && chance(2)) {  // get past magic and version now and then
      if (f[0].size() < 6) f[0].resize(6);
      poke(f[0], L::kMagic, kMagic);
      poke(f[0], L::kVersion, kVersion);
    }
    return f;
  }

  void mutate(Frames& f) {
    const int n = between(1, 3);
    for (int i = 0; i < n; ++i) mutate_once(f);
  }

 private:
  // Modulo bias does not matter here, and the distributions are slow in the ASan build.
  int between(int lo, int hi) { return lo + static_cast<int>(rng_() % (hi - lo + 1)); }
  bool chance(int one_in) { return between(1, one_in) == 1; }

  std::string name() {
    static constexpr std::string_view kChars = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.-";
    std::string s(between(1, kNameSize - 1), ' ');
    for (char& c : s) c = kChars[between(0, kChars.size() - 1)];
    return s;
  }

  Frame bytes(std::size_t n) {
    Frame b(n + 7);
    for (std::size_t i = 0; i < n; i += 8) poke(b, i, rng_());
    b.resize(n);
    return b;
  }

  double value(bool any_bits) {
    if (any_bits && chance(4)) return std::bit_cast<double>(rng_());  // NaN payloads too
    return std::uniform_real_distribution<double>(-1e3, 1e3)(rng_);
  }

  Array array() {
    const auto tag = static_cast<Tag>(between(1, 9));
    if (tag == Tag::Text) {
      Frame b = bytes(between(0, 40));
      return Array::text(std::string(reinterpret_cast<const char*>(b.data()), b.size()));
    }
    const bool physics = tag == Tag::Poses || tag == Tag::Forces || tag == Tag::Responses || tag == Tag::Stats;
    const auto rows = static_cast<std::uint32_t>(tag == Tag::Stats ? 1 : between(0, 3));
    const auto cols = static_cast<std::uint32_t>(tag == Tag::Poses       ? kPoseWidth
                                                 : tag == Tag::Forces    ? kForceWidth
                                                 : tag == Tag::Responses ? kResponseWidth
                                                 : tag == Tag::Stats     ? kStatsWidth
                                                 : tag == Tag::Points    ? 3
                                                                         : between(0, 6));
    std::vector<double> v(std::size_t{rows} * cols);
    for (double& x : v) x = value(!physics);
    return Array::of(tag, rows, cols, std::move(v));
  }

  std::uint32_t interesting_u32() {
    static constexpr std::uint32_t kValues[] = {0, 1, 2, 3, 6, 13, 64, 65, 0x7fffffff, 0x80000000, 0xffffffff, 0x10000};
    return chance(3) ? static_cast<std::uint32_t>(rng_()) : kValues[between(0, std::size(kValues) - 1)];
  }

  double interesting_double() {
    static constexpr double kValues[] = {0.0,
                                         -0.0,
                                         1.0,
                                         -1.0,
                                         std::numeric_limits<double>::quiet_NaN(),
                                         std::numeric_limits<double>::infinity(),
                                         -std::numeric_limits<double>::infinity(),
                                         std::numeric_limits<double>::denorm_min()};
    return chance(4) ? std::bit_cast<double>(rng_()) : kValues[between(0, std::size(kValues) - 1)];
  }

  std::size_t pick_frame(const Frames& f) {
    return chance(2) ? 0 : static_cast<std::size_t>(between(0, static_cast<int>(f.size()) - 1));
  }

  // Writes v at offset when the frame is long enough (mutations must not overflow either).
  template <class T>
  void put(Frame& frame, std::size_t offset, T v) {
    if (offset + sizeof v <= frame.size()) poke(frame, offset, v);
  }

  void mutate_once(Frames& f) {
    if (f.empty()) {
      f.push_back(bytes(between(0, 100)));
      return;
    }
    Frame& head = f[0];
    switch (between(0, 9)) {
      case 0: {  // bit flip
        Frame& frame = f[pick_frame(f)];
        if (!frame.empty()) frame[between(0, frame.size() - 1)] ^= static_cast<std::byte>(1u << between(0, 7));
        break;
      }
      case 1: {  // truncation
        Frame& frame = f[pick_frame(f)];
        frame.resize(between(0, frame.size()));
        break;
      }
      case 2: {  // extension
        Frame& frame = f[pick_frame(f)];
        const Frame extra = bytes(between(1, 16));
        frame.insert(frame.end(), extra.begin(), extra.end());
        break;
      }
      case 3: {  // descriptor field
        static constexpr std::size_t kFields[] = {L::kTag, L::kDType, L::kRows, L::kCols};
        const std::size_t field = kFields[between(0, 3)];
        const std::size_t at = L::header_size(between(0, 5)) + field;
        if (field < L::kRows)
          put(head, at, static_cast<std::uint16_t>(between(0, 8)));
        else
          put(head, at, interesting_u32());
        break;
      }
      case 4: {  // fixed header field
        switch (between(0, 5)) {
          case 0:
            put(head, L::kArrayCount, interesting_u32());
            break;
          case 1:
            put(head, L::kType, static_cast<std::uint16_t>(between(0, 15)));
            break;
          case 2:
            put(head, L::kRanks, interesting_u32());
            break;
          case 3:
            put(head, L::kT0, interesting_double());
            break;
          case 4:
            put(head, L::kT1, interesting_double());
            break;
          case 5:
            put(head, L::kName + between(0, kNameSize - 1), static_cast<char>(rng_()));
            break;
        }
        break;
      }
      case 5:  // frame dropped
        f.erase(f.begin() + between(0, f.size() - 1));
        break;
      case 6:  // frame duplicated or added
        f.insert(f.begin() + between(0, f.size()), chance(2) ? f[pick_frame(f)] : bytes(between(0, 64)));
        break;
      case 7: {  // payload value
        Frame& frame = f[pick_frame(f)];
        if (frame.size() >= sizeof(double))
          put(frame, sizeof(double) * between(0, frame.size() / sizeof(double) - 1), interesting_double());
        break;
      }
      case 8: {  // reshape with a matching payload: only the shape rules can object
        const int a = between(0, 5);
        const auto rows = static_cast<std::uint32_t>(between(0, 3));
        const auto cols = static_cast<std::uint32_t>(between(0, 14));
        put(head, L::header_size(a) + L::kRows, rows);
        put(head, L::header_size(a) + L::kCols, cols);
        if (static_cast<std::size_t>(a) + 1 < f.size()) f[a + 1].resize(rows * cols * 8);
        break;
      }
      case 9:  // frames swapped
        std::swap(f[between(0, f.size() - 1)], f[between(0, f.size() - 1)]);
        break;
    }
  }

  std::mt19937_64 rng_;
};

bool same_bytes(const std::vector<zmq::message_t>& a, const Frames& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].size() != b[i].size() || (!b[i].empty() && std::memcmp(a[i].data(), b[i].data(), b[i].size()) != 0))
      return false;
  return true;
}

enum class Outcome { Decoded, Refused };

// Fails the test (returning nullopt) on anything but the two allowed outcomes.
std::optional<Outcome> check(const Frames& frames) {
  try {
    const Message m = testing::decode_bytes(frames);
    if (!same_bytes(encode(m), frames)) {
      ADD_FAILURE() << "decoded message does not encode back to its bytes";
      return std::nullopt;
    }
    return Outcome::Decoded;
  } catch (const ProtocolError&) {
    return Outcome::Refused;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw something other than ProtocolError: " << e.what();
  } catch (...) {
    ADD_FAILURE() << "threw something other than ProtocolError";
  }
  return std::nullopt;
}

TEST(Fuzz, DecodeRefusesOrRoundTrips) {
  const auto start = std::chrono::steady_clock::now();
  Fuzzer fuzz(20240521);
  std::size_t cases = 0, decoded = 0, refused = 0;
  const auto run = [&](const Frames& frames) {
    ++cases;
    const auto outcome = check(frames);
    if (!outcome) return false;
    (*outcome == Outcome::Decoded ? decoded : refused) += 1;
    return true;
  };
  for (int base = 0; base < kBases; ++base) {
    const Frames valid = testing::to_bytes(encode(fuzz.valid_message()));
    ASSERT_TRUE(run(valid)) << "case " << cases;
    ASSERT_TRUE(run(fuzz.random_frames())) << "case " << cases;
    for (int i = 0; i < kMutantsPerBase; ++i) {
      Frames mutant = valid;
      fuzz.mutate(mutant);
      ASSERT_TRUE(run(mutant)) << "case " << cases;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(cases, 200000u);
  // Both outcomes must be well exercised, or the mutations stopped reaching the decoder.
  EXPECT_GT(decoded, cases / 10);
  EXPECT_GT(refused, cases / 3);
  std::printf("%zu cases in %.2f s: %zu decoded, %zu refused\n", cases, seconds, decoded, refused);
}

}  // namespace
}  // namespace cosim::protocol
