// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "mrpt_krp_plugin/dataset/dataset_generator.h"

namespace krp {

/// The dataset card as JSON (counts, every parameter, seed) and as Markdown for people.
/// The JSON is what a model manifest hashes to name the data it was trained on.
std::string datasetCardJson(const DatasetCard& card, const DatasetParams& params, const DatasetInputs& in);
std::string datasetCardMarkdown(const DatasetCard& card, const DatasetParams& params, const DatasetInputs& in);

}  // namespace krp
