#include "app/montecarlo/mc_stuck_hook.h"

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "core/user_error.h"

namespace rangesim::app::mc {

namespace {

class StuckRunner : public McPointRunner {
 public:
  McTrial trial(long long) override {
    for (;;) std::this_thread::sleep_for(std::chrono::hours(1));  // only _Exit ends it
  }
};

class StuckPointModel : public McModel {
 public:
  StuckPointModel(std::unique_ptr<McModel> inner, std::uint64_t stuck_key)
      : inner_(std::move(inner)), stuck_key_(stuck_key) {}
  const char* unit() const override { return inner_->unit(); }
  double metres_per_unit() const override { return inner_->metres_per_unit(); }
  std::unique_ptr<McPointRunner> point(double signal, double background, std::uint64_t key) const override {
    if (key == stuck_key_) return std::make_unique<StuckRunner>();
    return inner_->point(signal, background, key);
  }

 private:
  std::unique_ptr<McModel> inner_;
  std::uint64_t stuck_key_;  // point_key of the hooked grid point
};

}  // namespace

std::unique_ptr<McModel> with_stuck_point_hook(std::unique_ptr<McModel> model, std::uint64_t seed) {
  const char* env = std::getenv(kStuckPointEnv);
  if (!env || !*env) return model;
  char* end = nullptr;
  const long long index = std::strtoll(env, &end, 10);
  if (*end != '\0' || index < 0)
    throw UserError(fmt::format("{}={}: allowed a grid index >= 0 (test hook)", kStuckPointEnv, env));
  return std::make_unique<StuckPointModel>(std::move(model), point_key(seed, static_cast<std::uint64_t>(index)));
}

}  // namespace rangesim::app::mc
