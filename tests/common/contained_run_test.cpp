// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/common/contained_run.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <stdexcept>

#include "mrpt_krp_plugin/common/input_error.h"
#include "support/input_error_message.h"

namespace krp {
namespace {

using test::inputErrorMessage;

TEST(ContainedRun, AReaderThatReturnsOrThrowsIsNoCrash) {
  EXPECT_EQ(inputErrorMessage([] { runContained([] {}, "log.rawlog", "the reader"); }), "");
  EXPECT_EQ(inputErrorMessage([] { runContained([] { throw std::runtime_error("bad record"); }, "log.rawlog", "the reader"); }),
            "");
}

TEST(ContainedRun, TheChildsInputErrorComesBackWithoutASecondRun) {
  // The parent's copy of `runs` stays 0 when only the child ran the work.
  int runs = 0;
  const std::string long_problem(100000, 'x');  // more than a pipe holds: the parent must read while the child writes
  try {
    runContained(
        [&] {
          ++runs;
          throw InputError("log.rawlog", "record 3 is truncated " + long_problem);
        },
        "log.rawlog", "the reader");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.input(), "log.rawlog");
    EXPECT_EQ(e.problem(), "record 3 is truncated " + long_problem);
  }
  EXPECT_EQ(runs, 0);
}

TEST(ContainedRun, ACrashBecomesAnErrorNamingTheInput) {
  const auto m = inputErrorMessage([] { runContained([] { std::abort(); }, "log.rawlog", "the reader"); });
  EXPECT_NE(m.find("log.rawlog"), std::string::npos) << m;
  EXPECT_NE(m.find("the reader crashed"), std::string::npos) << m;
  const auto exited = inputErrorMessage([] { runContained([] { ::_exit(7); }, "log.rawlog", "the reader"); });
  EXPECT_NE(exited.find("exit status 7"), std::string::npos) << exited;
}

TEST(ContainedRun, AReaderThatNeverReturnsIsStopped) {
  ContainedRunParams p;
  p.timeout_s = 1;
  const auto m = inputErrorMessage([&] { runContained([] { for (;;) ::pause(); }, "log.rawlog", "the reader", p); });
  EXPECT_NE(m.find("did not finish in 1 s"), std::string::npos) << m;
}

}  // namespace
}  // namespace krp
