// Presets that inherit (`base = ...`), plain values, `--set KEY=VALUE` and the cross-key checks
// at load time (core/preset.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <fstream>

#include "core/preset.h"
#include "core/user_error.h"

namespace rangesim {
namespace {

namespace fs = std::filesystem;

// Writes `text` to <temp>/preset_inherit/<name> and returns the path.
std::string write(const std::string& name, const std::string& text) {
  const fs::path dir = fs::path(::testing::TempDir()) / "preset_inherit";
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

TEST(PresetInherit, AFewLinesOverAShippedPreset) {
  const std::string path = write("fast.toml", R"(base = "ls-conventional"
[timing]
clock_Hz = 50e6
[multisampling]
samplings = { value = 3, source = "what-if" }
)");
  const ParamSet p = load_preset(path);
  const ParamSet ref = load_preset("ls-conventional");
  EXPECT_EQ(p.sensor_id(), "ls-conventional");
  EXPECT_EQ(p.origin(), path);
  EXPECT_DOUBLE_EQ(p.real("timing.clock_Hz"), 50e6);
  EXPECT_EQ(p.at("timing.clock_Hz").source, "user");
  EXPECT_EQ(p.at("timing.clock_Hz").file, path);
  EXPECT_EQ(p.integer("multisampling.samplings"), 3);
  EXPECT_EQ(p.at("multisampling.samplings").source, "what-if");
  // Everything else is the base's, with the base's source and file.
  EXPECT_DOUBLE_EQ(p.real("pixel.integration_time_s"), ref.real("pixel.integration_time_s"));
  EXPECT_EQ(p.at("pixel.integration_time_s").source, ref.at("pixel.integration_time_s").source);
  EXPECT_EQ(p.at("pixel.integration_time_s").file, ref.origin());
  EXPECT_EQ(p.values().size(), ref.values().size());
}

TEST(PresetInherit, ChainsOfRelativePaths) {
  write("a.toml", "base = \"tof-spad\"\n[tdc]\ncolumns_per_tdc = 2\n");
  const std::string b =
      write("b.toml", "base = \"a.toml\"\n[sensor]\nid = \"tof-spad\"\n[laser]\nrepetition_rate_Hz = 20e6\n");
  const ParamSet p = load_preset(b);
  EXPECT_EQ(p.integer("tdc.columns_per_tdc"), 2);
  EXPECT_DOUBLE_EQ(p.real("laser.repetition_rate_Hz"), 20e6);
}

TEST(PresetInherit, BadBasesNameTheFileAndTheReason) {
  const std::string missing = write("missing.toml", "base = \"no-such-preset\"\n");
  EXPECT_NE(error_of([&] { load_preset(missing); }).find("base = \"no-such-preset\""), std::string::npos);
  const std::string nofile = write("nofile.toml", "base = \"nowhere/x.toml\"\n");
  EXPECT_NE(error_of([&] { load_preset(nofile); }).find("no such preset file"), std::string::npos);
  write("c1.toml", "base = \"c2.toml\"\n");
  const std::string c2 = write("c2.toml", "base = \"c1.toml\"\n");
  const std::string circle = error_of([&] { load_preset(c2); });
  EXPECT_NE(circle.find("inherits in a circle"), std::string::npos) << circle;
  EXPECT_NE(circle.find("c1.toml"), std::string::npos) << circle;
  const std::string other = write("other.toml", "base = \"tof-spad\"\n[sensor]\nid = \"tof-lockin\"\n");
  EXPECT_NE(error_of([&] { load_preset(other); }).find("differs from its base's sensor tof-spad"), std::string::npos);
  const std::string notstring = write("notstring.toml", "base = 3\n");
  EXPECT_NE(error_of([&] { load_preset(notstring); }).find("base must be a preset id or a path"), std::string::npos);
  const std::string unknown = write("unknown.toml", "base = \"tof-spad\"\n[tdc]\nbitz = 3\n");
  const std::string u = error_of([&] { load_preset(unknown); });
  EXPECT_NE(u.find("unknown key 'tdc.bitz' for sensor tof-spad"), std::string::npos) << u;
  EXPECT_NE(u.find(unknown), std::string::npos) << u;
}

TEST(PresetInherit, CrossKeyChecksRunAtLoadNamingBothKeys) {
  const std::string path = write("wide.toml", "base = \"ls-conventional\"\n[pixel]\ncolumns = 1024\n");
  const std::string e = error_of([&] { load_preset(path); });
  EXPECT_NE(e.find("timing.address_bits = 9"), std::string::npos) << e;
  EXPECT_NE(e.find("pixel.columns = 1024"), std::string::npos) << e;
  const std::string ok = write("wide_ok.toml", "base = \"wide.toml\"\n[timing]\naddress_bits = 10\n");
  EXPECT_EQ(load_preset(ok).integer("pixel.columns"), 1024);
}

TEST(PresetSet, AppliesAfterThePresetWithTheSameChecks) {
  ParamSet p = load_preset("ls-conventional");
  apply_settings(p, {"timing.clock_Hz=20e6", "comparator.threshold_mode=fixed", "multisampling.samplings=8"});
  EXPECT_DOUBLE_EQ(p.real("timing.clock_Hz"), 20e6);
  EXPECT_EQ(p.text("comparator.threshold_mode"), "fixed");
  EXPECT_EQ(p.integer("multisampling.samplings"), 8);
  EXPECT_EQ(p.at("timing.clock_Hz").source, "command line --set");
  const auto bad = [](const std::string& s) {
    ParamSet q = load_preset("ls-conventional");
    return error_of([&] { apply_settings(q, {s}); });
  };
  EXPECT_NE(bad("timing.clock_Hz").find("expected KEY=VALUE"), std::string::npos);
  EXPECT_NE(bad("timing.clok_Hz=1").find("no parameter 'timing.clok_Hz' for sensor ls-conventional"),
            std::string::npos);
  EXPECT_NE(bad("timing.clock_Hz=fast").find("is not a number"), std::string::npos);
  EXPECT_NE(bad("multisampling.samplings=65").find("integer in [1, 64]"), std::string::npos);
  EXPECT_NE(bad("multisampling.samplings=2.5").find("out of range"), std::string::npos);
  EXPECT_NE(bad("comparator.threshold_mode=best").find("one of \"tracking\" \"fixed\""), std::string::npos);
  EXPECT_NE(bad("pixel.columns=1024").find("timing.address_bits = 9 cannot address pixel.columns = 1024"),
            std::string::npos);
}

// UserError::key(): the key at fault, for callers that report it apart from the message (the
// Python module's rangesim.Error.key); the cross-key checks name the first of their keys.
TEST(PresetSet, ErrorsCarryTheKey) {
  const auto key_of = [](const std::string& s) {
    ParamSet q = load_preset("ls-conventional");
    try {
      apply_settings(q, {s});
    } catch (const UserError& e) {
      return e.key();
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(key_of("timing.clok_Hz=1"), "timing.clok_Hz");
  EXPECT_EQ(key_of("timing.clock_Hz=fast"), "timing.clock_Hz");
  EXPECT_EQ(key_of("multisampling.samplings=65"), "multisampling.samplings");
  EXPECT_EQ(key_of("comparator.threshold_mode=best"), "comparator.threshold_mode");
  EXPECT_EQ(key_of("pixel.columns=1024"), "timing.address_bits");
  EXPECT_EQ(key_of("timing.clock_Hz"), "");  // not KEY=VALUE: no key to name
}

}  // namespace
}  // namespace rangesim
