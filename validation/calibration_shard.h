// Physics calibration in shards: an item is a trial index; shard I plays trials i with
// i mod N = I of every kick (each kick keeps its own seed stream, so a trial's result does not
// depend on the split). Its result is, per kick, the observation (launch, roll distance, the
// rolling samples of the deceleration fit) and the drawn perturbations, null when the robot
// missed the ball, "fell" when it fell, "blocked" when it could not take its stance; numbers
// written exactly, so the merged fit has the bytes of an unsharded run.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "report/shard_file.h"
#include "validation/physics_calibration.h"

namespace foresight {

// The results of a calibration run with `shard` (`trials` per kick), in trial order.
nlohmann::json CalibrationShardResults(const PhysicsCalibration& calibration, const Shard& shard,
                                       int trials);

// Fills the kicks of `plan` (PlanPhysicsCalibration) from the shards, in trial order: the same
// as RunPhysicsCalibration. InputError when a result is malformed.
void MergeCalibrationShards(PhysicsCalibration& plan, int trials,
                            const std::vector<ShardPart>& parts);

}  // namespace foresight
