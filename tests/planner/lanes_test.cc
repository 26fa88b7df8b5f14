// The SIMD lanes' maths against the project's scalar functions (common/fast_math.h): the same
// operations in the same order, so every lane must have the scalar bits.
#include "planner/lanes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "common/random.h"
#include "planner/random_lanes.h"

namespace foresight {
namespace {

// Lanes filled from `next`, one value per lane.
template <typename Next>
Lanes Fill(Next&& next) {
  Lanes x{};
  for (int l = 0; l < kLanes; ++l) x[l] = next();
  return x;
}

TEST(LanesTest, SinCosLanesHasTheScalarBits) {
  RandomStream rng(StreamKey(18, 2));
  int compared = 0;
  for (int i = 0; i < 20000; ++i) {
    const double range = i % 2 == 0 ? 4.0 : 40.0;  // every quadrant, and several turns
    const Lanes x = Fill([&] { return range * (2.0 * rng.NextUniform() - 1.0); });
    Lanes s, c;
    SinCosLanes(x, &s, &c);
    for (int l = 0; l < kLanes; ++l) {
      double s_ref, c_ref;
      SinCos(x[l], &s_ref, &c_ref);
      ASSERT_EQ(s[l], s_ref) << x[l];
      ASSERT_EQ(c[l], c_ref) << x[l];
      ++compared;
    }
  }
  EXPECT_EQ(compared, 20000 * kLanes);
}

TEST(LanesTest, ExpFastLanesHasTheScalarBits) {
  RandomStream rng(StreamKey(18, 3));
  for (int i = 0; i < 20000; ++i) {
    const Lanes x = Fill([&] { return -60.0 + 70.0 * rng.NextUniform(); });
    const Lanes e = ExpFastLanes(x);
    for (int l = 0; l < kLanes; ++l) ASSERT_EQ(e[l], ExpFast(x[l])) << x[l];
  }
  // Beyond +-700 the lanes take the scalar function.
  const Lanes far = Fill([v = -720.0]() mutable { return v += 360.0; });
  const Lanes e = ExpFastLanes(far);
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(e[l], ExpFast(far[l])) << far[l];
}

TEST(LanesTest, StreamsInLanesHaveTheScalarStreamsBits) {
  for (std::uint64_t seed : {0ULL, 18ULL, ~0ULL}) {
    for (std::uint64_t first : {0ULL, 8ULL, 1000003ULL}) {
      const LaneBits key = StreamKeyLanes(seed, first, 5);
      for (int l = 0; l < kLanes; ++l) {
        ASSERT_EQ(key[l], StreamKey(seed, first + l, 5));
        RandomStream rng(key[l]);
        for (std::uint64_t draw = 1; draw <= 3; ++draw) {
          ASSERT_EQ(StreamBitsLanes(key, draw)[l], rng.NextBits());
        }
        RandomStream skipped(key[l], 2), walked(key[l]);
        walked.NextBits();
        walked.NextBits();
        ASSERT_EQ(skipped.NextBits(), walked.NextBits());
      }
    }
  }
}

// The ziggurat's fast path in lanes: a lane it keeps has NextNormal's bits; a lane it rejects is
// one whose scalar draw leaves the layer's rectangle (so the scalar draws more numbers).
TEST(LanesTest, NormalFastPathInLanesHasTheScalarBits) {
  const random_detail::ZigguratTables& t = random_detail::kZiggurat;
  int rejected = 0, draws = 0;
  for (std::uint64_t first = 0; first < 40000; first += kLanes) {
    const LaneBits key = StreamKeyLanes(7, first);
    LaneMask fast = BroadcastMask(-1);
    const Lanes normal = NormalFastLanes(StreamBitsLanes(key, 1), fast);
    for (int l = 0; l < kLanes; ++l) {
      ++draws;
      RandomStream bits(key[l]);
      const std::uint64_t b = bits.NextBits();
      const int layer = static_cast<int>(b & 127);
      const double u = 2.0 * (static_cast<double>(b >> 11) * 0x1.0p-53) - 1.0;
      const bool in_rectangle = u < t.ratio[layer] && u > -t.ratio[layer];
      ASSERT_EQ(fast[l] != 0, in_rectangle) << first + l;
      if (fast[l] == 0) {
        ++rejected;
        continue;
      }
      RandomStream rng(key[l]);
      const double expected = rng.NextNormal();
      ASSERT_EQ(std::memcmp(&normal[l], &expected, sizeof expected), 0) << first + l;
    }
  }
  // About 2.8 % of the 128-layer ziggurat's points lie outside their rectangle.
  EXPECT_GT(rejected, draws / 50);
  EXPECT_LT(rejected, draws / 25);
}

// Exp in lanes (no table) against the scalar Exp: every bit, over the range the normals' wedge
// and the potential use and beyond, and the scalar fallback past +-700.
TEST(LanesTest, ExpInLanesHasExpsBits) {
  int compared = 0;
  for (double x0 = -40.0; x0 < 40.0; x0 += 0.0137 * kLanes) {
    const Lanes x = Fill([x0, l = 0]() mutable { return x0 + 0.0137 * l++; });
    const Lanes e = ExpLanes(x);
    for (int l = 0; l < kLanes; ++l, ++compared) {
      const double expected = Exp(x[l]);
      ASSERT_EQ(std::memcmp(&e[l], &expected, sizeof expected), 0) << x[l];
    }
  }
  EXPECT_GT(compared, 5000);
  const Lanes far = Fill([v = -1080.0]() mutable { return v += 360.0; });
  const Lanes e = ExpLanes(far);
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(e[l], Exp(far[l])) << far[l];
}

// Whole normals in lanes (fast path, wedge, fresh draws after a rejection) against
// RandomStream::NextNormal, 40 normals deep into each of 16,000 streams: every lane that is not
// reported at the tail has the scalar normal's bits and its stream stands where the scalar
// stream stands; a lane reported at the tail is one whose scalar normal lies beyond the tail's
// start (the scalar stream draws it; that stream is then left).
// RandomStream::NextNormal of each lane's stream (`state` as in NextBitsLanes), lanes that reach
// the tail set in `tail`: the wedge in lanes checked against the sequential stream.
Lanes NextNormalLanes(LaneBits& state, LaneMask& tail) {
  const LaneBits bits = NextBitsLanes(state, BroadcastMask(-1));
  LaneMask fast = BroadcastMask(-1);
  Lanes value = NormalFastLanes(bits, fast);
  if (!All(fast)) NormalEdgeLanes(bits, ~fast, state, value, tail);
  return value;
}

TEST(LanesTest, NormalsInLanesHaveTheScalarBits) {
  const random_detail::ZigguratTables& t = random_detail::kZiggurat;
  int slow = 0, tails = 0, normals = 0;
  for (std::uint64_t first = 0; first < 16000; first += kLanes) {
    const LaneBits key = StreamKeyLanes(11, first);
    LaneBits state = key;
    std::vector<RandomStream> scalar;
    for (int l = 0; l < kLanes; ++l) scalar.emplace_back(key[l]);
    LaneMask gone = BroadcastMask(0);
    for (int k = 0; k < 40; ++k) {
      LaneMask tail = BroadcastMask(0);
      const LaneBits before = state;
      const Lanes normal = NextNormalLanes(state, tail);
      for (int l = 0; l < kLanes; ++l) {
        const double expected = scalar[static_cast<std::size_t>(l)].NextNormal();
        if (gone[l]) continue;
        if (tail[l]) {
          // Drawn by the scalar stream in DrawSampleLanes; this stream is not compared further.
          ++tails;
          gone[l] = -1;
          ASSERT_GT(std::abs(expected), t.x[1]) << first + l;
          continue;
        }
        ASSERT_EQ(std::memcmp(&normal[l], &expected, sizeof expected), 0) << first + l << " " << k;
        ++normals;
        slow += state[l] != before[l] + kGoldenGamma;
        // The stream stands where the scalar one does.
        RandomStream lane(state[l]), copy = scalar[static_cast<std::size_t>(l)];
        ASSERT_EQ(lane.NextBits(), copy.NextBits()) << first + l << " " << k;
      }
    }
  }
  EXPECT_GT(slow, normals / 200);  // wedges (each draws a uniform) and rejections
  EXPECT_GT(tails, 0);
}

// IndexedNormal in lanes: the fast paths of 20 normals of each of 24,000 keys, then every miss
// finished together (FinishMissedNormals, the tail lanes by the scalar IndexedNormal), against
// the scalar IndexedNormal bit by bit.
TEST(LanesTest, IndexedNormalsInLanesHaveTheScalarBits) {
  constexpr int kIndices = 20;
  int misses = 0, tails = 0;
  for (std::uint64_t first = 0; first < 24000; first += kLanes) {
    const LaneBits key = StreamKeyLanes(29, first);
    double normal[kIndices][kLanes];  // doubles: a missed normal is written through its address
    std::vector<MissedNormal> missed;
    for (int k = 0; k < kIndices; ++k) {
      LaneBits bits;
      LaneMask fast = BroadcastMask(-1);
      Store(IndexedNormalFastLanes(key, static_cast<std::uint64_t>(k), &bits, fast), normal[k]);
      for (int l = 0; l < kLanes; ++l) {
        if (!fast[l]) missed.push_back({&normal[k][l], key[l], static_cast<std::uint64_t>(k), bits[l]});
      }
    }
    FinishMissedNormals(missed.data(), static_cast<int>(missed.size()));
    misses += static_cast<int>(missed.size());
    for (int k = 0; k < kIndices; ++k) {
      for (int l = 0; l < kLanes; ++l) {
        const double expected = IndexedNormal(key[l], static_cast<std::uint64_t>(k));
        tails += std::abs(expected) > random_detail::kZiggurat.x[1];
        ASSERT_EQ(std::memcmp(&normal[k][l], &expected, sizeof expected), 0)
            << first + l << " " << k;
      }
    }
  }
  EXPECT_GT(misses, 24000 * kIndices / 50);  // about 2.8 % of normals
  EXPECT_GT(tails, 100);                     // about 6 in 10,000 normals
}

TEST(LanesTest, GatherAnyAndAll) {
  double table[100];
  for (int i = 0; i < 100; ++i) table[i] = 0.5 * i - 7.0;
  LaneBits index{};
  for (int l = 0; l < kLanes; ++l) index[l] = static_cast<std::uint64_t>(99 - 13 * l);
  const Lanes v = Gather(table, index);
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(v[l], table[99 - 13 * l]);
  EXPECT_FALSE(Any(BroadcastMask(0)));
  EXPECT_TRUE(All(BroadcastMask(-1)));
  for (int l = 0; l < kLanes; ++l) {
    LaneMask one = BroadcastMask(0);
    one[l] = -1;
    EXPECT_TRUE(Any(one)) << l;
    EXPECT_FALSE(All(one) && kLanes > 1) << l;
    EXPECT_FALSE(All(~one)) << l;
  }
}

TEST(LanesTest, RoundingTiesGoAwayFromZeroAsTheScalarOne) {
  // -0.25 and -1e-300: rounded to -0.0 by the AVX rounding, +0.0 by the conversion; alike here.
  for (double x : {0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 1e6 + 0.5, -3.0, 0.49999999999999994, -0.25,
                   -1e-300}) {
    const Lanes rounded = RoundToIntLanes(Broadcast(x));
    EXPECT_EQ(rounded[0], fast_math_detail::RoundToInt(x)) << x;
    EXPECT_EQ(static_cast<std::int64_t>(IntegerBits(rounded)[0]),
              static_cast<std::int64_t>(fast_math_detail::RoundToInt(x)))
        << x;
  }
}

TEST(LanesTest, SelectMinAndClampFollowTheStandardLibrary) {
  const Lanes a = Broadcast(1.0), b = Broadcast(2.0);
  EXPECT_EQ(Min(a, b)[0], 1.0);
  EXPECT_EQ(Min(b, a)[0], 1.0);
  EXPECT_EQ(Clamp(Broadcast(-3.0), Broadcast(0.0), Broadcast(1.0))[0], 0.0);
  EXPECT_EQ(Clamp(Broadcast(3.0), Broadcast(0.0), Broadcast(1.0))[0], 1.0);
  EXPECT_EQ(Abs(Broadcast(-0.25))[0], 0.25);
  EXPECT_TRUE(Any(Broadcast(1.0) > 0.5));
  EXPECT_FALSE(Any(Broadcast(1.0) > 1.5));
}

}  // namespace
}  // namespace foresight
