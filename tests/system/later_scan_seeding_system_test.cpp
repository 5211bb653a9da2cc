// SPDX-License-Identifier: BSD-3-Clause
// System test: a seeded filter that is unsure of its pose relocalizes later scans and gives their
// hypotheses particles (MclParams::later_scans), so a first answer that is wrong everywhere is
// not the end of the trial. The hypotheses come from a stand-in for the relocalizer.
#include <gtest/gtest.h>

#include <cmath>

#include "mrpt_krp_plugin/filter/filter_spread.h"
#include "mrpt_krp_plugin/filter/mcl_localizer.h"
#include "mrpt_krp_plugin/filter/seeded_initializer.h"
#include "support/seeded_drives.h"

namespace krp {
namespace {

using test::RoomTrial;

// The first scan's only answer is a wrong place and there is no uniform share, so no particle
// starts near the truth; every later scan's answer is the truth.
struct WrongFirstAnswer {
  const RoomTrial& drive;
  std::size_t step = 0;
  int calls = 0;
  Ranking operator()(const mrpt::obs::CObservation2DRangeScan&) {
    ++calls;
    const auto& truth = drive.trial.truth[step];
    Ranking r;
    r.hypotheses = {test::hypothesisAt(step == 0 ? mrpt::math::TPose2D(truth.x > 4.0 ? 1.5 : 6.5, 4.5, truth.phi + 2.0) : truth, 1.0)};
    return r;
  }
};

struct DriveResult {
  double final_error_m = 0.0;
  int later_scans = 0;
  int calls = 0;
};

DriveResult drive(const RoomTrial& d, const MclParams& mp) {
  auto answer = std::make_shared<WrongFirstAnswer>(WrongFirstAnswer{d});
  SeededInitParams sp;
  sp.uniform_fraction = 0.0;
  auto init = std::make_shared<SeededInitializer>([answer](const auto& scan) { return (*answer)(scan); }, sp);
  MclLocalizer loc(d.room, init, mp);
  DriveResult out;
  MclEstimate e;
  for (std::size_t i = 0; i < d.steps.size(); ++i) {
    answer->step = i;
    e = loc.update(d.steps[i]);
    out.later_scans += e.later_scan_relocalized;
  }
  const auto& truth = d.trial.truth.back();
  out.final_error_m = std::hypot(e.mean.x - truth.x, e.mean.y - truth.y);
  out.calls = answer->calls;
  return out;
}

TEST(SystemLaterScans, AWrongFirstAnswerIsRecoveredFromLaterScans) {
  const RoomTrial d;
  MclParams mp;
  mp.seed = 2;
  // The stand-in's wrong place fits this room's scans badly, yet a filter without the look-alike
  // guard's widening would read tight there: here every estimate reads unsure.
  mp.later_scans.unsure = {1e-9, 1e-9};
  const auto without = drive(d, mp);
  EXPECT_GT(without.final_error_m, 1.0) << "nothing near the truth, nothing to recover";
  EXPECT_EQ(without.later_scans, 0);
  EXPECT_EQ(without.calls, 1);

  mp.later_scans.enabled = true;
  const auto with = drive(d, mp);
  EXPECT_LT(with.final_error_m, 0.2);
  EXPECT_EQ(with.later_scans, mp.later_scans.max_scans) << "7 unsure updates after the first, capped";
  EXPECT_EQ(with.calls, 1 + mp.later_scans.max_scans);
}

TEST(SystemLaterScans, OnlyAnUnsureFilterRelocalizesALaterScan) {
  const RoomTrial d;
  int calls = 0;
  std::size_t step = 0;
  auto init = std::make_shared<SeededInitializer>([&](const auto&) {
    ++calls;
    Ranking r;
    r.hypotheses = {test::hypothesisAt(d.trial.truth[step], 1.0)};
    return r;
  });
  MclParams mp;
  mp.seed = 2;
  mp.later_scans.enabled = true;
  MclLocalizer loc(d.room, init, mp);
  bool previous_unsure = false;
  int later = 0;
  for (step = 0; step < d.steps.size(); ++step) {
    const auto e = loc.update(d.steps[step]);
    EXPECT_EQ(e.later_scan_relocalized, step > 0 && previous_unsure) << "update " << step;
    later += e.later_scan_relocalized;
    // Without a guard the reported covariance is the particles' own, and no scan reads unexplained.
    previous_unsure = !isConcentrated(filterSpread(e.cov), mp.later_scans.unsure);
  }
  EXPECT_FALSE(previous_unsure) << "seeded at the truth, the filter ends sure of it";
  EXPECT_EQ(calls, 1 + later);
}

}  // namespace
}  // namespace krp
