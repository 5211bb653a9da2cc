// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/thesis_comparison_report.h"

#include <sstream>

#include "mrpt_krp_plugin/bench/report_format.h"

namespace krp {
namespace {

std::string percent(double share) { return formatNumber(100.0 * share) + " %"; }

void classificationRow(std::ostringstream& o, const std::string& name, const ClassificationScores& s) {
  o << "| " << name << " | " << formatNumber(s.precision) << " | " << formatNumber(s.recall) << " | "
    << formatNumber(s.f1) << " | " << percent(s.accuracy) << " | " << s.unanswered << " |\n";
}

void optionalPose(std::ostringstream& o, const std::optional<mrpt::math::TPose2D>& p) {
  if (p)
    o << "," << p->x << "," << p->y << "," << p->phi;
  else
    o << ",,,";
}

}  // namespace

std::string thesisComparisonMarkdown(const ThesisComparison& c, const std::string& command) {
  const auto& p = c.params;
  std::ostringstream o;
  o << "# The thesis's comparisons with classical methods: " << c.world << ", " << c.lidar << "\n\n"
    << "Command:\n\n```\n" << command << "\n```\n\n"
    << "Models: `" << c.models_dir << "`. Seed " << p.seed << ". Per zone, " << p.references_per_zone
    << " reference submaps (the SIFT/ORB database) and " << p.tests_per_zone
    << " held-out submaps (every method answers the same ones), from poses drawn uniformly over the zone's free "
       "space with any heading, each scan simulated in the map "
    << (p.clutter ? "with its own unmapped objects (the world's clutter settings)" : "as mapped") << ". "
    << "The held-out poses are fresh draws, not the training dataset's test split; the CNN never saw these scenes, "
       "but its training scenes came from the same zones.\n\n"
    << "## Zone classification (the thesis's Table 4.4)\n\n"
    << "SIFT and ORB: up to " << p.features.max_features
    << " features of the submap's occupancy image, matched against each zone's pooled reference descriptors; "
       "the zone with the most matches passing Lowe's ratio test ("
    << p.features.ratio
    << ") wins, none when no zone has any. CNN: the shipped classifier, as the relocalizer runs it (the turn of the "
       "submap it is surest of). Precision, recall and F1 are averaged over the zones.\n\n"
    << "| method | precision | recall | F1 | accuracy | no answer |\n|---|---|---|---|---|---|\n";
  classificationRow(o, "SIFT", c.sift);
  classificationRow(o, "ORB", c.orb);
  classificationRow(o, "CNN (shipped)", c.cnn);
  o << "\nThe thesis (two zones, Gazebo): SIFT 0.55, ORB 0.80, GoogLeNet 0.975 (precision = recall = F1).\n\n"
    << "## Pose from the submap (the thesis's Table 4.5)\n\n"
    << "ICP: MRPT's point-to-point ICP of the scan against the map's obstacle cells, started at the zone's centre "
       "(area centroid) with the true heading (which favours it), pairing points up to "
    << p.icp_start_correspondence_m
    << " m apart at first. Keypoint alignment: the keypoint model's detections in the classifier's two most likely "
       "zones, aligned to their landmarks by RANSAC and weighted least squares; the best-fitting pose is taken "
       "whether or not the relocalizer would call it credible. RMSE and median over the samples a method answered; "
       "\"right\" is within "
    << p.right_within_m << " m and " << p.right_within_deg << " deg, of all samples.\n\n"
    << "| method | answered | position RMSE m | median position error m | heading RMSE deg | right |\n"
       "|---|---|---|---|---|---|\n";
  for (const auto& a : c.alignment)
    o << "| " << a.method << " | " << a.answered << " / " << a.samples << " | " << formatNumber(a.rmse_m) << " | "
      << formatNumber(a.median_m) << " | " << formatNumber(a.rmse_deg) << " | " << percent(a.right_share) << " |\n";
  o << "\nThe thesis: average RMSE 3.719 (ICP) against 0.376 (YOLOv8-pose alignment).\n\n"
    << "Per-sample answers: `samples.csv`.\n";
  return o.str();
}

std::string thesisComparisonCsv(const ThesisComparison& c) {
  std::ostringstream o;
  o.precision(9);
  o << "zone,truth_x,truth_y,truth_phi,cnn,sift,orb,keypoints_x,keypoints_y,keypoints_phi,keypoints_icp_x,"
       "keypoints_icp_y,keypoints_icp_phi,icp_from_centre_x,icp_from_centre_y,icp_from_centre_phi\n";
  for (const auto& s : c.samples) {
    o << s.zone << "," << s.truth.x << "," << s.truth.y << "," << s.truth.phi << "," << s.cnn << "," << s.sift << ","
      << s.orb;
    optionalPose(o, s.keypoints);
    optionalPose(o, s.keypoints_icp);
    optionalPose(o, s.icp_from_centre);
    o << "\n";
  }
  return o.str();
}

}  // namespace krp
