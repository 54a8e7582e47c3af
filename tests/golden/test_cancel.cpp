// A progress callback that throws cancels a golden evaluation (the Python module's Ctrl-C): the
// exception comes out of evaluate_sensor for every registered sensor, the worker threads of the
// parallel models are joined first (an unjoined std::thread would end the process), and the
// callback is not called again.
#include <gtest/gtest.h>

#include <stdexcept>

#include "core/preset.h"
#include "core/sensor_registry.h"
#include "golden/common/evaluate_sensor.h"

namespace rangesim::golden {
namespace {

struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("cancelled") {}
};

int g_calls = 0;
void cancel_at_first_call(int, int) {
  ++g_calls;
  throw Cancelled();
}

TEST(GoldenCancel, ProgressThatThrowsStopsEveryModel) {
  int modelled = 0;
  for (const auto& s : sensors()) {
    if (!golden_model(s.id)) continue;
    ++modelled;
    const ParamSet params = load_preset(s.id);
    g_calls = 0;
    EXPECT_THROW(evaluate_sensor(params, &cancel_at_first_call), Cancelled) << s.id;
    EXPECT_EQ(g_calls, 1) << s.id;
  }
  EXPECT_GE(modelled, 4);
}

}  // namespace
}  // namespace rangesim::golden
