// How much of the attacking game the case base covers with retrieval: the share of
// random 2-vs-2 attack situations for which Algorithm 2 retrieves a case, per region and overall.
//
// The situations (our assumptions; the paper gives the regions only as figures, Fig. 11, 12), for
// the team defending cyan (attacking +x; for yellow everything is mirrored in x):
//   ball:      uniform over one region of AttackRegions() (a rectangle, |y| ranges taken on both
//              wings), each region sampled alike; the overall shares weight the regions by area;
//   teammate 1 within 0.5 m behind the ball: uniform over the half disc of radius 0.5 m on the
//              side away from the attacked goal (the robot about to take the ball);
//   teammate 2 within 1.5 m of the ball: uniform over the disc of radius 1.5 m (the supporter);
//   both face the attacked goal and are clamped onto the field;
//   opponents: the paper's DG configuration (Fig. 11a): a defender uniform over its home region
//              x in [0.3, 2.0] m, |y| <= 1.3 m (the attacked half up to the penalty area, which
//              defenders may not enter, sec. 5.2) and a goalie uniform over the penalty area,
//              x in [2.05, 2.6] m, |y| <= 0.65 m.
// Counted per situation: in_scope, at least one case passes the ball filter (sim_B > thr_b,
// the rough figure BallScopeCoverage gives on a grid); retrieved, at least one case is a
// candidate (Algorithm 1), which is exactly when one is retrieved (Algorithm 2); cooperative,
// the retrieved case has two teammates (a pass); too_far and blocked split in_scope - retrieved
// by the deepest test a case reached.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cbr/case_base.h"
#include "cbr/retrieval_params.h"
#include "models/field_box.h"

namespace foresight {

// A region of ball positions for the team defending cyan: x in [x_min, x_max], |y| in
// [abs_y_min, abs_y_max] (both wings).
struct AttackRegion {
  std::string name;
  double x_min_m = 0.0, x_max_m = 0.0;
  double abs_y_min_m = 0.0, abs_y_max_m = 0.0;
  double Area() const { return 2.0 * (x_max_m - x_min_m) * (abs_y_max_m - abs_y_min_m); }
};

// back, center, side, front, front_side, corner: the regions of models/cases/README.md made
// into rectangles that tile x in [-2.0, 2.6] m, |y| <= 1.6 m but the goal mouth (x > 2.3 m,
// |y| < 0.5 m, the goalie's).
std::vector<AttackRegion> AttackRegions();

// The random attacks: the assumptions listed at the top of this file, as data.
struct AttackSpec {
  std::vector<AttackRegion> regions = AttackRegions();
  double behind_radius_m = 0.5;   // teammate 1: the half disc behind the ball
  double support_radius_m = 1.5;  // teammate 2: the disc around the ball
  FieldBox defender{0.3, 2.0, -1.3, 1.3};  // for the team defending cyan
  FieldBox goalie{2.05, 2.6, -0.65, 0.65};
};

struct RegionCoverage {
  std::string name;
  double area_m2 = 0.0;
  int samples = 0;
  int in_scope = 0;
  int retrieved = 0;
  int cooperative = 0;
  // In scope but nothing retrieved: the deepest test any case reached failed there.
  int too_far = 0;  // no case passed the cost test (thr_c)
  int blocked = 0;  // some case passed it, but every such case's ball path was blocked
};

struct AttackCoverage {
  std::vector<RegionCoverage> regions;
  // Area-weighted over the regions.
  double in_scope = 0.0;
  double retrieved = 0.0;
  double cooperative = 0.0;
};

// `samples_per_region` situations per region, drawn from streams keyed by `seed` and the region
// (common/random.h), so the figures are reproducible.
AttackCoverage MeasureAttackCoverage(const LoadedCaseBase& base, DefendingGoal goal,
                                     const RetrievalParams& params, int samples_per_region,
                                     std::uint64_t seed, const AttackSpec& spec = AttackSpec{});

}  // namespace foresight
