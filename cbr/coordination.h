// Who coordinates (Ros et al. 2009, sec. 4.1). The robots' beliefs differ, so one robot decides:
// the one with the lowest id among those present (a robot that crashed or was removed stops
// being present once nothing was heard from it for a while). It names as coordinator the
// retriever closest to the ball by what it knows: its own distance and each teammate's last
// reported distance. Only the coordinator retrieves; it tells the team the case and the
// correspondence.
//
// Retrievers are the robots with the k lowest indices (decision: the paper leaves open which k
// of the n robots retrieve; the lowest ids keep the rule as simple as the selector's).
// Ties in distance go to the lower index.
#pragma once

#include <span>

namespace foresight {

// What one robot knows about each teammate (indexed by robot, its own entry included).
struct TeammateBelief {
  bool present = false;
  double ball_distance_m = 0.0;
  // In a kick motion: the ball at its front is about to leave (or has just left), so the
  // situation a retrieval would see now is not the one the case would be played in.
  bool kicking = false;
};

// The lowest present index (the robot itself counts as present), or -1 if none is.
int Selector(std::span<const TeammateBelief> team);

// The present retriever (index < retrievers) closest to the ball; -1 if none is present, or if
// a present retriever has not reported its distance yet (+infinity: the selector waits for it
// rather than guess, e.g. in the first step of a game).
int ChooseCoordinator(std::span<const TeammateBelief> team, int retrievers);

}  // namespace foresight
