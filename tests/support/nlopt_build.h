#pragma once

/// Tests of results that need NLopt (vantage/analysis/build_options.h): in a build without it
/// (VANTAGE_WITH_NLOPT=OFF) the part did not run, so such a test is skipped; the module's
/// nlopt_build_test.cc checks that the part says so instead.

#include <gtest/gtest.h>

#include "vantage/analysis/build_options.h"

/// Skips the current test when vantage was built without NLopt.
#define VANTAGE_SKIP_WITHOUT_NLOPT() \
  if (!::vantage::built_with_nlopt()) GTEST_SKIP() << "vantage " << ::vantage::kWithoutNlopt
