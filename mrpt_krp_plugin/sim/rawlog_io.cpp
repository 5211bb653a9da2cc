// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/sim/rawlog_io.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/contained_run.h"
#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

mrpt::obs::CActionRobotMovement2D::TMotionModelOptions OdometryModelParams::toMrpt() const {
  mrpt::obs::CActionRobotMovement2D::TMotionModelOptions o;
  o.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
  o.gaussianModel.minStdXY = static_cast<float>(min_std_xy_m);
  o.gaussianModel.minStdPHI = static_cast<float>(min_std_phi_deg * M_PI / 180.0);
  o.gaussianModel.a1 = static_cast<float>(xy_std_per_m);
  o.gaussianModel.a2 = static_cast<float>(xy_std_per_rad);
  o.gaussianModel.a3 = static_cast<float>(phi_std_per_m_deg * M_PI / 180.0);
  o.gaussianModel.a4 = static_cast<float>(phi_std_per_rad);
  return o;
}

RawlogStep makeRawlogStep(const mrpt::poses::CPose2D& odometry_increment,
                          const mrpt::obs::CObservation2DRangeScan::Ptr& scan, const OdometryModelParams& model) {
  RawlogStep s;
  s.action = mrpt::obs::CActionCollection::Create();
  mrpt::obs::CActionRobotMovement2D move;
  move.computeFromOdometry(odometry_increment, model.toMrpt());
  s.action->insert(move);
  s.observations = mrpt::obs::CSensoryFrame::Create();
  s.observations->insert(scan);
  return s;
}

std::vector<RawlogStep> trialToSteps(const Trial& trial, const OdometryModelParams& model) {
  std::vector<RawlogStep> steps;
  for (size_t i = 0; i < trial.scans.size(); ++i) steps.push_back(makeRawlogStep(trial.odometry[i], trial.scans[i], model));
  return steps;
}

void writeTrialRawlog(const Trial& trial, const std::string& rawlog_path, const std::string& ground_truth_path,
                      const OdometryModelParams& model) {
  const auto steps = trialToSteps(trial, model);
  AtomicFile out(rawlog_path);
  {
    mrpt::io::CFileGZOutputStream f(out.tempPath());
    auto arch = mrpt::serialization::archiveFrom(f);
    for (const auto& s : steps) arch << *s.action << *s.observations;
  }
  std::ostringstream gt;
  gt.precision(9);
  gt << "# step x_m y_m phi_rad distance_m   (grid frame; trial seed " << trial.seed << ")\n";
  for (size_t i = 0; i < trial.truth.size(); ++i)
    gt << i << " " << trial.truth[i].x << " " << trial.truth[i].y << " " << trial.truth[i].phi << " "
       << trial.distance_m[i] << "\n";
  writeFileAtomically(ground_truth_path, gt.str());
  out.commit();
}

namespace {
std::vector<RawlogStep> parseRawlog(const std::string& path) {
  std::vector<RawlogStep> steps;
  mrpt::io::CFileGZInputStream f(path);
  auto arch = mrpt::serialization::archiveFrom(f);
  mrpt::obs::CActionCollection::Ptr pending_action;
  size_t records = 0;
  for (;;) {
    mrpt::serialization::CSerializable::Ptr obj;
    try {
      obj = arch.ReadObject();
    } catch (const mrpt::serialization::CExceptionEOF&) {
      break;
    } catch (const std::exception& e) {
      std::string what = e.what();
      if (what.size() > 200) what = what.substr(0, 200) + "...";
      throw InputError(path, "record " + std::to_string(records) + " is unreadable or truncated (" + what + ")");
    }
    ++records;
    if (auto a = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(obj)) {
      pending_action = a;
    } else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj)) {
      steps.push_back({pending_action, sf});
      pending_action.reset();
    } else if (auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obj)) {
      // Observations-only rawlogs: each scan is its own step with no odometry.
      auto frame = mrpt::obs::CSensoryFrame::Create();
      frame->insert(scan);
      steps.push_back({nullptr, frame});
    }  // other observation types are skipped: the filter uses 2D scans only
  }
  if (steps.empty()) throw InputError(path, "the rawlog holds no 2D laser scan");
  return steps;
}
}  // namespace

std::vector<RawlogStep> readRawlog(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError(path, "file does not exist");
  // MRPT's deserializer crashes on some corrupt records (found by tests/fuzz/rawlog_fuzzer): a
  // first read in a child process turns that into an error naming the file.
  runContained([&] { parseRawlog(path); }, path, "MRPT's rawlog deserializer");
  return parseRawlog(path);
}

std::vector<mrpt::math::TPose2D> readGroundTruth(const std::string& path, std::vector<double>* distance_m) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot open the ground-truth file");
  std::vector<mrpt::math::TPose2D> poses;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    double step, x, y, phi, d = 0.0;
    if (!(ls >> step >> x >> y >> phi))
      throw InputError(path, "line " + std::to_string(line_no) + " is not 'step x y phi [distance]'");
    if (!(ls >> d)) d = 0.0;
    poses.emplace_back(x, y, phi);
    if (distance_m) distance_m->push_back(d);
  }
  if (poses.empty()) throw InputError(path, "no ground-truth pose");
  return poses;
}

}  // namespace krp
