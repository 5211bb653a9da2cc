// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/relocalize/correlative_matcher.h"
#include "mrpt_krp_plugin/sim/floor_plan.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "support/test_maps.h"

namespace krp {
namespace {

mrpt::obs::CObservation2DRangeScan::Ptr scanAt(const mrpt::maps::COccupancyGridMap2D& map, const mrpt::poses::CPose2D& pose) {
  Rng rng(5);
  return ScanSimulator(lidarProfileByName("omni_12m")).simulate(map, pose, rng);
}

/// A bare 9 x 7 m rectangle: every pose and its 180 deg twin look alike.
mrpt::maps::COccupancyGridMap2D bareRectangle() {
  FloorPlan plan(9.0, 7.0, 0.05);
  plan.building(0.5, 0.5, 8.5, 6.5);
  return plan.toGrid();
}

TEST(CorrelativeMatcher, FindsThePoseOverTheWholeMap) {
  const auto room = test::asymmetricRoom();
  const mrpt::poses::CPose2D truth(5.52, 2.07, 0.8);
  const CorrelativeMatcher matcher(room);
  const auto sols = matcher.match(*scanAt(room, truth));
  ASSERT_FALSE(sols.empty());
  EXPECT_NEAR(sols[0].pose.x, truth.x(), 0.1);
  EXPECT_NEAR(sols[0].pose.y, truth.y(), 0.1);
  // One search cell and a couple of heading steps: ICP refines from there.
  EXPECT_LT(std::abs(mrpt::math::wrapToPi(sols[0].pose.phi - truth.phi())), 2.5 * M_PI / 180.0);
  EXPECT_GT(sols[0].score, 0.7);
  // Its 180 deg twin explains most of the walls; only the L wall and the block tell them apart.
  if (sols.size() > 1) {
    EXPECT_LT(sols[1].score, 0.9 * sols[0].score) << "the room has no symmetry";
  }
}

TEST(CorrelativeMatcher, BranchAndBoundFindsWhatExhaustiveSearchFinds) {
  const auto room = test::asymmetricRoom();
  const auto scan = scanAt(room, mrpt::poses::CPose2D(2.0, 4.5, -2.2));
  CorrelativeMatcherParams exhaustive;
  exhaustive.angular_step_deg = 10.0;  // keeps the exhaustive run short
  exhaustive.depth = 0;
  exhaustive.solutions = 1;
  CorrelativeMatcherParams bnb = exhaustive;
  bnb.depth = 5;
  const CorrelativeMatcher a(room, exhaustive), b(room, bnb);
  const auto sa = a.match(*scan), sb = b.match(*scan);
  ASSERT_EQ(sa.size(), 1u);
  ASSERT_EQ(sb.size(), 1u);
  EXPECT_DOUBLE_EQ(sa[0].score, sb[0].score);
  EXPECT_DOUBLE_EQ(sa[0].pose.x, sb[0].pose.x);
  EXPECT_DOUBLE_EQ(sa[0].pose.y, sb[0].pose.y);
  EXPECT_LT(b.lastNodesScored(), a.lastNodesScored() / 5) << "the bounds should prune most of the search";
}

/// Two matchers built on `map` with `baseline` and `variant` search scans from the twin rooms'
/// poses: every solution must be the same, one by one, and each search give at least
/// `min_solutions`; returns the nodes each scored over all the scans.
std::pair<long long, long long> sameAnswersOnTwinRoomScans(const mrpt::maps::COccupancyGridMap2D& map,
                                                            const CorrelativeMatcherParams& baseline,
                                                            const CorrelativeMatcherParams& variant,
                                                            size_t min_solutions) {
  const CorrelativeMatcher a_matcher(map, baseline), b_matcher(map, variant);
  long long a_nodes = 0, b_nodes = 0;
  for (const auto& pose : {mrpt::poses::CPose2D(2.0, 2.0, 0.4), mrpt::poses::CPose2D(5.5, 4.0, -1.9),
                           mrpt::poses::CPose2D(16.2, 1.5, 2.8)}) {
    const auto scan = scanAt(map, pose);
    const auto a = a_matcher.match(*scan);
    a_nodes += a_matcher.lastNodesScored();
    const auto b = b_matcher.match(*scan);
    b_nodes += b_matcher.lastNodesScored();
    EXPECT_EQ(a.size(), b.size());
    EXPECT_GE(a.size(), min_solutions);
    for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
      EXPECT_DOUBLE_EQ(a[i].score, b[i].score) << i;
      EXPECT_DOUBLE_EQ(a[i].pose.x, b[i].pose.x) << i;
      EXPECT_DOUBLE_EQ(a[i].pose.y, b[i].pose.y) << i;
      EXPECT_DOUBLE_EQ(a[i].pose.phi, b[i].pose.phi) << i;
    }
  }
  return {a_nodes, b_nodes};
}

// A search for several solutions starts each after the first from the best candidate an earlier
// one passed that is still allowed: the same places and scores as starting each from min_score,
// for fewer nodes where the earlier searches passed look-alikes (two rooms alike, each with its
// own turned twins; the twin room holds a look-alike, so at least two solutions).
TEST(CorrelativeMatcher, LaterSolutionsStartedWarmAreTheSameForFewerNodes) {
  CorrelativeMatcherParams cold_params;
  cold_params.solutions = 4;
  cold_params.warm_start_later_solutions = false;
  CorrelativeMatcherParams warm_params = cold_params;
  warm_params.warm_start_later_solutions = true;
  const auto [cold_nodes, warm_nodes] = sameAnswersOnTwinRoomScans(test::twinRooms(), cold_params, warm_params, 2);
  EXPECT_LT(warm_nodes, cold_nodes);
}

// The roots of every heading visited in one order, highest bound first, reach the best place
// sooner than heading after heading, and prune the other headings from its score on: the same
// places and scores for fewer nodes.
TEST(CorrelativeMatcher, RootsAcrossHeadingsFindTheSameForFewerNodes) {
  CorrelativeMatcherParams per_heading_params;
  per_heading_params.solutions = 2;
  per_heading_params.roots_across_headings = false;
  CorrelativeMatcherParams across_params = per_heading_params;
  across_params.roots_across_headings = true;
  const auto [per_heading_nodes, across_nodes] =
      sameAnswersOnTwinRoomScans(test::twinRooms(), per_heading_params, across_params, 1);
  EXPECT_LT(across_nodes, per_heading_nodes);
}

// Where walls meet at right angles, the headings that line the scan's walls up with the map's
// hold the answer: the narrowed search finds the pose the full turn finds, for a fraction of the
// nodes. A map without a clear wall direction keeps every heading.
TEST(CorrelativeMatcher, AWallHeadingWindowFindsTheSamePoseForFewerNodes) {
  const auto room = test::asymmetricRoom();
  const CorrelativeMatcher matcher(room);
  for (const auto& truth : {mrpt::poses::CPose2D(5.52, 2.07, 0.8), mrpt::poses::CPose2D(2.0, 4.5, -2.2)}) {
    const auto scan = scanAt(room, truth);
    const auto full = matcher.match(*scan);
    const long long full_nodes = matcher.lastNodesScored();
    MatchRequest narrowed;
    narrowed.wall_heading_window_deg = 3.0;
    const auto windowed = matcher.match(*scan, narrowed);
    ASSERT_FALSE(full.empty());
    ASSERT_FALSE(windowed.empty());
    EXPECT_DOUBLE_EQ(windowed[0].score, full[0].score);
    EXPECT_DOUBLE_EQ(windowed[0].pose.x, full[0].pose.x);
    EXPECT_DOUBLE_EQ(windowed[0].pose.y, full[0].pose.y);
    EXPECT_DOUBLE_EQ(windowed[0].pose.phi, full[0].pose.phi);
    EXPECT_LT(matcher.lastNodesScored(), full_nodes / 4) << "about 24 of 360 headings tried";
  }
  // The same window on a map whose walls have no dominant direction changes nothing.
  CorrelativeMatcherParams strict;
  strict.min_wall_support = 1.01;  // no map reaches it: every heading stays
  const CorrelativeMatcher unsure(room, strict);
  const auto scan = scanAt(room, mrpt::poses::CPose2D(5.52, 2.07, 0.8));
  unsure.match(*scan);
  const long long every = unsure.lastNodesScored();
  MatchRequest narrowed;
  narrowed.wall_heading_window_deg = 3.0;
  unsure.match(*scan, narrowed);
  EXPECT_EQ(unsure.lastNodesScored(), every);
  EXPECT_FALSE(MatchRequest::validWallHeadingWindow(-1.0));
  EXPECT_FALSE(MatchRequest::validWallHeadingWindow(46.0));
  EXPECT_TRUE(MatchRequest::validWallHeadingWindow(0.0));
  // The refusals name the accepted range from the limit itself, so the two cannot drift apart.
  EXPECT_EQ(MatchRequest::wallHeadingWindowRange(), "0 (every heading) to 45");
}

TEST(CorrelativeMatcher, ASymmetricRoomGivesTwoEqualSolutions) {
  const auto map = bareRectangle();
  const CorrelativeMatcher matcher(map);
  const auto sols = matcher.match(*scanAt(map, mrpt::poses::CPose2D(3.0, 2.5, 0.3)));
  ASSERT_EQ(sols.size(), 2u);
  EXPECT_GT(sols[1].score, 0.95 * sols[0].score);
  const bool first_is_truth = std::hypot(sols[0].pose.x - 3.0, sols[0].pose.y - 2.5) < 0.2;
  const auto& twin = first_is_truth ? sols[1] : sols[0];
  EXPECT_NEAR(twin.pose.x, 9.0 - 3.0, 0.2);
  EXPECT_NEAR(twin.pose.y, 7.0 - 2.5, 0.2);
}

// The margin around the score grids only lets the bound skip its edge checks: without it (every
// node near the map's edge takes the checked path) the search finds the same places and scores.
TEST(CorrelativeMatcher, TheGridMarginChangesTheCostNotTheAnswer) {
  const auto room = test::asymmetricRoom();
  const auto scan = scanAt(room, mrpt::poses::CPose2D(2.0, 4.5, -2.2));
  CorrelativeMatcherParams edge_checked;
  edge_checked.margin_m = 0.0;
  const CorrelativeMatcher with_margin(room), without(room, edge_checked);
  const auto a = with_margin.match(*scan), b = without.match(*scan);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a[i].score, b[i].score, 1e-9) << i;
    EXPECT_DOUBLE_EQ(a[i].pose.x, b[i].pose.x) << i;
    EXPECT_DOUBLE_EQ(a[i].pose.y, b[i].pose.y) << i;
    EXPECT_DOUBLE_EQ(a[i].pose.phi, b[i].pose.phi) << i;
  }
  // A pose off the map scores its returns that land on it, in both.
  const mrpt::math::TPose2D off_map{-1.0, 3.0, 0.0};
  EXPECT_NEAR(with_margin.scoreAt(*scan, off_map), without.scoreAt(*scan, off_map), 1e-9);
  CorrelativeMatcherParams negative;
  negative.margin_m = -1.0;
  EXPECT_THROW(CorrelativeMatcher(room, negative), std::invalid_argument);
}

// A zone region decides between the twins: the search stays inside it. (What it costs against
// the whole map's depends on the order the roots come in: with roots across headings the whole
// map's search reaches a twin at once, so no cost is pinned here.)
TEST(CorrelativeMatcher, ARegionKeepsTheSearchInsideIt) {
  const auto map = bareRectangle();
  const CorrelativeMatcher matcher(map);
  const auto scan = scanAt(map, mrpt::poses::CPose2D(3.0, 2.5, 0.3));
  const auto whole = matcher.match(*scan);
  const Zone west{"west", {{0.0, 0.0}, {4.5, 0.0}, {4.5, 7.0}, {0.0, 7.0}}};
  const Zone east{"east", {{4.5, 0.0}, {9.0, 0.0}, {9.0, 7.0}, {4.5, 7.0}}};
  for (const auto& [zone, expected_x, expected_y] :
       {std::tuple{west, 3.0, 2.5}, std::tuple{east, 9.0 - 3.0, 7.0 - 2.5}}) {
    const auto sols = matcher.match(*scan, MatchRequest::within(matcher.regionOf({zone})));
    ASSERT_FALSE(sols.empty()) << zone.name;
    EXPECT_NEAR(sols[0].pose.x, expected_x, 0.2) << zone.name;
    EXPECT_NEAR(sols[0].pose.y, expected_y, 0.2) << zone.name;
    for (const auto& s : sols) EXPECT_EQ(s.pose.x < 4.5, zone.name == "west") << zone.name << " " << s.pose.x;
  }
  ASSERT_FALSE(whole.empty());
  EXPECT_THROW(matcher.match(*scan, MatchRequest::within(cv::Mat::ones(3, 3, CV_8U))), std::invalid_argument);
}

// scoreAt is match()'s own score at a pose; a minimum score that high prunes the search to what
// can beat it, which makes checking a known answer for look-alikes cheap.
TEST(CorrelativeMatcher, AKnownScoreBoundsTheSearch) {
  const auto map = bareRectangle();
  const CorrelativeMatcher matcher(map);
  const auto scan = scanAt(map, mrpt::poses::CPose2D(3.0, 2.5, 0.3));
  const auto open = matcher.match(*scan);
  const long long open_nodes = matcher.lastNodesScored();
  ASSERT_EQ(open.size(), 2u);
  EXPECT_DOUBLE_EQ(matcher.scoreAt(*scan, open[0].pose), open[0].score);
  EXPECT_LT(matcher.scoreAt(*scan, {open[0].pose.x + 1.0, open[0].pose.y, open[0].pose.phi}), 0.8 * open[0].score);

  MatchRequest bounded;
  bounded.min_score = matcher.scoreAt(*scan, open[0].pose) - 0.05;
  const auto found = matcher.match(*scan, bounded);
  EXPECT_LT(matcher.lastNodesScored(), open_nodes) << "a high minimum should prune the search";
  ASSERT_EQ(found.size(), 2u) << "the 180 deg twin scores as well as the answer";
  EXPECT_DOUBLE_EQ(found[0].score, open[0].score);

  // Excluding the answer leaves its twin as the one other place, in one pass.
  bounded.excluded = {{open[0].pose.x, open[0].pose.y}};
  bounded.solutions = 1;
  const auto others = matcher.match(*scan, bounded);
  ASSERT_EQ(others.size(), 1u);
  EXPECT_NEAR(others[0].pose.x, open[1].pose.x, 1e-9);
  EXPECT_NEAR(others[0].pose.y, open[1].pose.y, 1e-9);

  bounded = {};
  bounded.min_score = open[0].score + 0.01;
  EXPECT_TRUE(matcher.match(*scan, bounded).empty()) << "nothing beats the best";
}

// A charge that rules out the best place (and everything within the exclusion distance of it)
// leaves what excluding it leaves: the charged search, best-first, agrees with the depth-first
// one on the answer and its score.
TEST(CorrelativeMatcher, AChargeThatRulesOutAPlaceLeavesWhatExcludingItLeaves) {
  const auto room = test::asymmetricRoom();
  CorrelativeMatcherParams params;
  params.solutions = 1;
  const CorrelativeMatcher matcher(room, params);
  const auto scan = scanAt(room, mrpt::poses::CPose2D(5.52, 2.07, 0.8));
  const auto open = matcher.match(*scan);
  ASSERT_EQ(open.size(), 1u);
  const mrpt::math::TPoint2D best(open[0].pose.x, open[0].pose.y);

  MatchRequest excluding;
  excluding.excluded = {best};
  const auto expected = matcher.match(*scan, excluding);
  ASSERT_EQ(expected.size(), 1u);

  MatchRequest charging;
  charging.leaf_penalty = [&](const mrpt::math::TPose2D& p, double) {
    return std::hypot(p.x - best.x, p.y - best.y) < params.exclusion_m ? 1.0 : 0.0;
  };
  const auto charged = matcher.match(*scan, charging);
  ASSERT_EQ(charged.size(), 1u);
  EXPECT_DOUBLE_EQ(charged[0].score, expected[0].score);
  EXPECT_DOUBLE_EQ(charged[0].pose.x, expected[0].pose.x);
  EXPECT_DOUBLE_EQ(charged[0].pose.y, expected[0].pose.y);
  EXPECT_DOUBLE_EQ(charged[0].pose.phi, expected[0].pose.phi);
  EXPECT_FALSE(matcher.lastSearchCutShort());
}

// A charge that varies over the map: branch and bound answers what the exhaustive charged
// search does, and the answer's score is its endpoint score less its charge.
TEST(CorrelativeMatcher, ChargedBranchAndBoundFindsWhatExhaustiveChargedSearchFinds) {
  const auto room = test::asymmetricRoom();
  const auto scan = scanAt(room, mrpt::poses::CPose2D(2.0, 4.5, -2.2));
  const auto charge = [](const mrpt::math::TPose2D& p) { return 0.15 * (1.0 + std::sin(3.0 * p.x + 2.0 * p.y + p.phi)); };
  MatchRequest charging;
  int stopped_early = 0;
  charging.leaf_penalty = [&](const mrpt::math::TPose2D& p, double enough) {
    EXPECT_GE(enough, 0.0);
    // What a caller that stops counting may return: anything at least `enough`, once reached.
    if (charge(p) >= enough) {
      ++stopped_early;
      return std::max(enough, 0.3);
    }
    return charge(p);
  };
  CorrelativeMatcherParams exhaustive;
  exhaustive.angular_step_deg = 10.0;
  exhaustive.depth = 0;
  exhaustive.solutions = 1;
  CorrelativeMatcherParams bnb = exhaustive;
  bnb.depth = 5;
  const CorrelativeMatcher a(room, exhaustive), b(room, bnb);
  const auto sa = a.match(*scan, charging), sb = b.match(*scan, charging);
  ASSERT_EQ(sa.size(), 1u);
  ASSERT_EQ(sb.size(), 1u);
  EXPECT_DOUBLE_EQ(sa[0].score, sb[0].score);
  EXPECT_DOUBLE_EQ(sa[0].pose.x, sb[0].pose.x);
  EXPECT_DOUBLE_EQ(sa[0].pose.y, sb[0].pose.y);
  EXPECT_DOUBLE_EQ(sb[0].score, b.scoreAt(*scan, sb[0].pose) - charge(sb[0].pose));
  EXPECT_GT(stopped_early, 0) << "the search should tell the charge when it may stop";
  EXPECT_LT(b.lastNodesScored(), a.lastNodesScored() / 5) << "the bounds should prune most of the charged search too";
  const auto uncharged = b.match(*scan, MatchRequest{});
  ASSERT_EQ(uncharged.size(), 1u);
  EXPECT_GT(uncharged[0].score, sb[0].score);
}

// A bound that stops reading returns once its node cannot beat what the search must beat changes
// the cost, not the search: every kind of search gives the same answers, scores and node counts
// with it as without it, and it does stop early on most of a high-bar search's nodes.
TEST(CorrelativeMatcher, ABoundThatStopsEarlyChangesTheCostNotTheSearch) {
  const auto room = test::asymmetricRoom();
  CorrelativeMatcherParams reading_all;
  reading_all.stop_bound_early = false;
  CorrelativeMatcherParams stopping = reading_all;
  stopping.stop_bound_early = true;
  const CorrelativeMatcher all(room, reading_all), early(room, stopping);
  const auto scan = scanAt(room, mrpt::poses::CPose2D(2.0, 4.5, -2.2));
  MatchRequest high_bar;
  high_bar.min_score = all.scoreAt(*scan, {2.0, 4.5, -2.2}) - 0.3;
  MatchRequest charged = high_bar;
  charged.leaf_penalty = [](const mrpt::math::TPose2D& p, double) { return 0.1 * (1.0 + std::sin(3.0 * p.x + 2.0 * p.y)); };
  const MatchRequest whole_map;
  long long stopped_on_high_bar = 0;
  for (const MatchRequest* request : std::array<const MatchRequest*, 3>{&whole_map, &high_bar, &charged}) {
    const auto a = all.match(*scan, *request);
    const auto b = early.match(*scan, *request);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_FALSE(a.empty());
    for (size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].score, b[i].score);
      EXPECT_EQ(a[i].pose.x, b[i].pose.x);
      EXPECT_EQ(a[i].pose.y, b[i].pose.y);
      EXPECT_EQ(a[i].pose.phi, b[i].pose.phi);
    }
    EXPECT_EQ(all.lastNodesScored(), early.lastNodesScored());
    EXPECT_EQ(all.lastNodesStoppedEarly(), 0);
    EXPECT_LE(early.lastNodesStoppedEarly(), early.lastNodesScored());
    if (request != &whole_map) stopped_on_high_bar += early.lastNodesStoppedEarly();
  }
  EXPECT_GT(stopped_on_high_bar, 0) << "a high bar should let some bounds stop early";
  // scoreAt reads every return whatever the setting: it is a score, not a bound to beat.
  EXPECT_EQ(all.scoreAt(*scan, {1.0, 1.0, 0.5}), early.scoreAt(*scan, {1.0, 1.0, 0.5}));
}

// A search out of its node budget answers with the best place it charged, which is no better
// than the exact answer, and says that it was cut short; a negative charge is refused.
/// One solution, every place west of x = 4.5 m charged 0.2: a charge that moves the answer.
MatchRequest chargedWestOfMiddle() {
  MatchRequest charging;
  charging.solutions = 1;
  charging.leaf_penalty = [](const mrpt::math::TPose2D& p, double) { return p.x < 4.5 ? 0.2 : 0.0; };
  return charging;
}

TEST(CorrelativeMatcher, AChargedSearchOutOfBudgetSaysSoAndANegativeChargeIsRefused) {
  const auto map = bareRectangle();
  const CorrelativeMatcher matcher(map);
  const auto scan = scanAt(map, mrpt::poses::CPose2D(3.0, 2.5, 0.3));
  auto charging = chargedWestOfMiddle();
  const auto exact = matcher.match(*scan, charging);
  ASSERT_EQ(exact.size(), 1u);
  EXPECT_FALSE(matcher.lastSearchCutShort());
  const long long nodes = matcher.lastNodesScored();
  charging.max_nodes_scored = nodes / 2;
  const auto cut = matcher.match(*scan, charging);
  EXPECT_TRUE(matcher.lastSearchCutShort());
  EXPECT_LE(matcher.lastNodesScored(), nodes / 2 + 4) << "stops within one expansion of the budget";
  if (!cut.empty()) {
    EXPECT_LE(cut[0].score, exact[0].score);
  }
  charging.max_nodes_scored = 0;
  charging.leaf_penalty = [](const mrpt::math::TPose2D&, double) { return -0.1; };
  EXPECT_THROW(matcher.match(*scan, charging), std::invalid_argument);
}

// A charged search run in slices scores the same nodes and ends with the same answer as one run
// at once, with and without a node budget, and a slice stops within one expansion of its size.
TEST(CorrelativeMatcher, ASearchRunInSlicesEndsAsOneRunAtOnce) {
  const auto map = bareRectangle();
  const CorrelativeMatcher matcher(map);
  const auto scan = scanAt(map, mrpt::poses::CPose2D(3.0, 2.5, 0.3));
  auto charging = chargedWestOfMiddle();
  charging.excluded = {{3.0, 2.5}};  // as the look-alike guard asks: anywhere but here
  const auto whole = matcher.match(*scan, charging);
  ASSERT_EQ(whole.size(), 1u);
  const long long whole_nodes = matcher.lastNodesScored();
  // The first slice bounds every root whatever its size; the rest are split into slices.
  const auto probe = matcher.startSearch(*scan, charging);
  ASSERT_FALSE(matcher.resume(*probe, 1));
  const long long roots = probe->nodesScored();
  ASSERT_LT(roots + 40, whole_nodes) << "the search should go on well past its roots";
  const long long slice = (whole_nodes - roots) / 8;
  for (const long long budget : {0LL, roots + (whole_nodes - roots) / 2}) {
    charging.max_nodes_scored = budget;
    const auto at_once = matcher.match(*scan, charging);
    const long long at_once_nodes = matcher.lastNodesScored();
    const bool at_once_cut = matcher.lastSearchCutShort();
    const auto search = matcher.startSearch(*scan, charging);
    int slices = 0;
    long long before = 0;
    while (!matcher.resume(*search, slice)) {
      ++slices;
      EXPECT_FALSE(search->finished());
      // The first slice also bounds the roots; the others stop within one node's children.
      if (slices > 1) {
        EXPECT_LE(search->nodesScored() - before, slice + 4) << "slice " << slices;
      }
      before = search->nodesScored();
    }
    EXPECT_GE(slices, budget > 0 ? 3 : 7) << "budget " << budget;
    EXPECT_TRUE(search->finished());
    EXPECT_EQ(search->nodesScored(), at_once_nodes) << "budget " << budget;
    EXPECT_EQ(search->cutShort(), at_once_cut) << "budget " << budget;
    // What krp-bench-matcher reads after the guard's search: that search's count alone, not the
    // match() before it added in.
    EXPECT_EQ(matcher.lastNodesScored(), search->nodesScored()) << "budget " << budget;
    EXPECT_EQ(matcher.lastSearchCutShort(), search->cutShort()) << "budget " << budget;
    ASSERT_EQ(search->solution().has_value(), !at_once.empty()) << "budget " << budget;
    if (!at_once.empty()) {
      EXPECT_EQ(search->solution()->score, at_once[0].score);
      EXPECT_EQ(search->solution()->pose.x, at_once[0].pose.x);
      EXPECT_EQ(search->solution()->pose.y, at_once[0].pose.y);
      EXPECT_EQ(search->solution()->pose.phi, at_once[0].pose.phi);
    }
    EXPECT_TRUE(matcher.resume(*search, slice)) << "a finished search stays finished";
  }
  // Resuming is for charged, one-solution searches; the others are refused when set up.
  EXPECT_THROW(matcher.startSearch(*scan, MatchRequest{}), std::invalid_argument);
  charging.solutions = 2;
  EXPECT_THROW(matcher.startSearch(*scan, charging), std::invalid_argument);
}

}  // namespace
}  // namespace krp
