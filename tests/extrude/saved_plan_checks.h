#pragma once
// The checks the clean-up passes' plan tests share: a saved plan from the random run, built,
// is closed and passes the shell checks (shell_checks.h), and agrees with its independent
// oracle (volume_oracle.h): its volume within 1e-6, and where the oracle is the unperturbed
// plan, its roof area too.
#include "extrude/extrude.h"
#include "shell_checks.h"
#include "support.h"
#include "volume_oracle.h"

#include <gtest/gtest.h>

#include <string>

namespace corbel::extrude::test {

// The saved plan built: closed, passing the shell checks, and without a warning unless
// `warningsAllowed` (a sweep that capped a loop of no area warns, and says so).
inline ExtrusionResult expectClean(const std::string& file, const ExtrusionSpec& spec, bool warningsAllowed = false) {
  ExtrusionResult r = extrude(spec);
  EXPECT_EQ(unpairedEdges(r.shell), 0u) << file;
  if (!warningsAllowed)
    for (const auto& w : r.shell.warnings) ADD_FAILURE() << file << ": warning: " << w;
  EXPECT_EQ(shellGeometryProblem(r.shell, spec), "") << file;
  return r;
}
inline ExtrusionResult expectClean(const std::string& file) { return expectClean(file, savedSpec(file)); }

// `kind`: the oracle the plan is known to have.
inline void expectCleanAndAgreeing(const std::string& file, VolumeOracle::Kind kind, bool warningsAllowed = false) {
  const ExtrusionSpec spec = savedSpec(file);
  const ExtrusionResult r = expectClean(file, spec, warningsAllowed);
  const VolumeOracle o = independentVolume(spec);
  ASSERT_EQ(o.kind, kind);
  const ShellMeasures m = measure(r.shell);
  EXPECT_NEAR(m.volume, o.volume, 1e-6 * o.volume);
  if (o.kind == VolumeOracle::Unperturbed) {
    EXPECT_NEAR(m.roofArea, o.roofArea, 1e-6 * o.roofArea);
  }
}

}  // namespace corbel::extrude::test
