// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/filter/amcl_kld_initializer.h"
#include "mrpt_krp_plugin/filter/uniform_initializer.h"

namespace krp {

/// Settings of every method the bench knows, so one flag set configures them all.
struct MethodSettings {
  UniformInitParams uniform;
  AmclKldParams amcl;
  std::size_t amcl_high_max_particles = 50000;  ///< `amcl-kld-50k`: amcl with a raised max
};

/// The method names: `uniform-mcl`, `amcl-kld`, `amcl-kld-50k`.
std::vector<std::string> methodNames();

/// A fresh initializer for a method; InputError listing the names for an unknown one.
std::shared_ptr<ParticleInitializer> makeInitializer(const std::string& name, const MethodSettings& settings);

}  // namespace krp
