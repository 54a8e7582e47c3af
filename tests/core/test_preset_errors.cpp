// Every class of bad preset input is a UserError whose message names the file (with the line
// where there is one), the key and the allowed range. Each case copies a real preset and edits
// one line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <string>

#include "core/params.h"
#include "core/preset.h"
#include "core/schemas.h"
#include "core/user_error.h"
#include "tests/core/preset_test_util.h"

namespace rangesim {
namespace {

using test::Edit;
using test::TempPreset;
using test::user_error_of;

std::string preset_text(const std::string& id) { return test::read_text(test::source_preset_path(id)); }

// The allowed range of a key, as the loader prints it.
std::string range_of(const std::string& sensor, const std::string& key) {
  const ParamSpec* spec = schema_for(sensor, "test").find(key);
  if (!spec) throw std::logic_error("no key " + key);
  return describe_range(*spec);
}

// Loads an edited preset and checks the UserError message.
struct Expect {
  bool line = true;                    // message carries "<file>:<line>" of the edited line
  std::string key;                     // full key, e.g. "pixel.columns" ("" = not checked)
  std::string range;                   // allowed range text ("" = not checked)
  std::vector<std::string> also = {};  // further substrings
};

void expect_load_error(const Edit& edit, const Expect& e) {
  TempPreset file(edit.text);
  const std::string msg = user_error_of([&] { load_preset_file(file.path()); });
  SCOPED_TRACE(msg);
  ASSERT_FALSE(msg.empty());
  EXPECT_NE(msg.find(file.path()), std::string::npos) << "message must name the file";
  if (e.line && edit.line > 0) {
    EXPECT_NE(msg.find(fmt::format("{}:{}", file.path(), edit.line)), std::string::npos)
        << "message must name the line " << edit.line;
  }
  if (!e.key.empty()) {
    EXPECT_NE(msg.find(e.key), std::string::npos) << "message must name the key " << e.key;
  }
  if (!e.range.empty()) {
    EXPECT_NE(msg.find(e.range), std::string::npos) << "message must give the range " << e.range;
  }
  for (const auto& s : e.also) EXPECT_NE(msg.find(s), std::string::npos) << "message must contain " << s;
  // The same through load_preset(path).
  EXPECT_EQ(user_error_of([&] { load_preset(file.path()); }), msg);
}

// ---- Sanity of the mechanism: an unedited copy loads; an integer literal is a valid Real. ----

TEST(PresetErrors, UneditedCopyLoads) {
  for (const auto& id : test::preset_ids()) {
    TempPreset file(preset_text(id));
    EXPECT_NO_THROW(load_preset_file(file.path())) << id;
  }
}

TEST(PresetErrors, IntegerLiteralIsAcceptedForARealKey) {
  const Edit e = test::replace_rhs(preset_text("tof-lockin"), "evaluation", "distance_m",
                                   R"({ value = 2, source = "assumed: test" })");
  TempPreset file(e.text);
  const ParamSet set = load_preset_file(file.path());
  EXPECT_DOUBLE_EQ(set.real("evaluation.distance_m"), 2.0);
  EXPECT_EQ(set.at("evaluation.distance_m").source, "assumed: test");
}

// ---- Unknown, missing and malformed keys. ----

TEST(PresetErrors, UnknownKey) {
  const Edit e = test::insert_after_header(preset_text("ls-demodulation"), "pixel",
                                           R"(bogus_gain = { value = 1.0, source = "assumed: test" })");
  expect_load_error(e, {true, "pixel.bogus_gain", "", {"unknown key", "ls-demodulation"}});
}

TEST(PresetErrors, UnknownSection) {
  std::string text = preset_text("tof-spad");
  Edit e;
  e.text = text + "\n[nonsense]\nx_s = { value = 1.0, source = \"assumed: test\" }\n";
  e.line = static_cast<int>(std::count(e.text.begin(), e.text.end(), '\n'));
  expect_load_error(e, {true, "nonsense.x_s", "", {"unknown key"}});
}

TEST(PresetErrors, MissingKey) {
  const std::string key = "pixel.fd1_capacitance_F";
  const Edit e = test::delete_line(preset_text("tof-lockin"), "pixel", "fd1_capacitance_F");
  expect_load_error(e, {false, key, range_of("tof-lockin", key), {"missing"}});
}

TEST(PresetErrors, MissingKeyInEachSensor) {
  // The last key of each schema, removed from its preset.
  for (const auto& id : test::preset_ids()) {
    SCOPED_TRACE(id);
    const std::string key = schema_for(id, "test").params.back().key;
    const auto dot = key.find('.');
    const Edit e = test::delete_line(preset_text(id), key.substr(0, dot), key.substr(dot + 1));
    expect_load_error(e, {false, key, range_of(id, key), {"missing"}});
  }
}

TEST(PresetErrors, WrongTypeStringForNumber) {
  const std::string key = "tdc.lsb_s";
  const Edit e =
      test::replace_rhs(preset_text("tof-spad"), "tdc", "lsb_s", R"({ value = "97e-12", source = "assumed: test" })");
  expect_load_error(e, {true, key, range_of("tof-spad", key), {"must be a number"}});
}

TEST(PresetErrors, WrongTypeStringForInteger) {
  const std::string key = "pixel.columns";
  const Edit e = test::replace_rhs(preset_text("ls-conventional"), "pixel", "columns",
                                   R"({ value = "375", source = "assumed: test" })");
  expect_load_error(e, {true, key, range_of("ls-conventional", key), {"must be an integer"}});
}

TEST(PresetErrors, FractionForInteger) {
  const std::string key = "tdc.bits";
  const Edit e =
      test::replace_rhs(preset_text("tof-spad"), "tdc", "bits", R"({ value = 10.5, source = "assumed: test" })");
  expect_load_error(e, {true, key, range_of("tof-spad", key), {"must be an integer"}});
}

TEST(PresetErrors, WrongTypeNumberForBoolean) {
  const std::string key = "histogram.coates_correction";
  const Edit e = test::replace_rhs(preset_text("tof-spad"), "histogram", "coates_correction",
                                   R"({ value = 1, source = "assumed: test" })");
  expect_load_error(e, {true, key, range_of("tof-spad", key), {}});
}

TEST(PresetErrors, WrongTextChoice) {
  const std::string key = "comparator.threshold_mode";
  const Edit e = test::replace_rhs(preset_text("ls-conventional"), "comparator", "threshold_mode",
                                   R"({ value = "adaptive", source = "assumed: test" })");
  expect_load_error(e, {true, key, range_of("ls-conventional", key), {"adaptive"}});
}

// ---- Out-of-range numbers. ----

TEST(PresetErrors, NegativeCapacitance) {
  const std::string key = "correlator.capacitance_plus_F";
  const Edit e = test::replace_rhs(preset_text("ls-demodulation"), "correlator", "capacitance_plus_F",
                                   R"({ value = -37e-15, source = "assumed: test" })");
  expect_load_error(e, {true, key, range_of("ls-demodulation", key), {"out of range"}});
}

TEST(PresetErrors, ZeroCapacitance) {
  struct Case {
    std::string id, section, name;
  };
  for (const Case& c : {Case{"ls-conventional", "pixel", "pd_capacitance_F"},
                        Case{"ls-demodulation", "correlator", "capacitance_minus_F"},
                        Case{"tof-lockin", "pixel", "fd2_capacitance_F"}}) {
    SCOPED_TRACE(c.id);
    const std::string key = c.section + "." + c.name;
    EXPECT_EQ(range_of(c.id, key).rfind("(0, ", 0), 0u) << "capacitance range must exclude 0";
    const Edit e =
        test::replace_rhs(preset_text(c.id), c.section, c.name, R"({ value = 0.0, source = "assumed: test" })");
    expect_load_error(e, {true, key, range_of(c.id, key), {"out of range"}});
  }
}

TEST(PresetErrors, ZeroBits) {
  struct Case {
    std::string id, section, name;
  };
  for (const Case& c :
       {Case{"ls-conventional", "comparator", "adc_bits"}, Case{"ls-demodulation", "comparator", "adc_bits"},
        Case{"tof-lockin", "readout", "adc_bits"}, Case{"tof-spad", "tdc", "bits"}}) {
    SCOPED_TRACE(c.id);
    const std::string key = c.section + "." + c.name;
    const Edit e =
        test::replace_rhs(preset_text(c.id), c.section, c.name, R"({ value = 0, source = "assumed: test" })");
    expect_load_error(e, {true, key, range_of(c.id, key), {"out of range"}});
  }
}

TEST(PresetErrors, NaN) {
  const std::string key = "spad.dead_time_s";
  const Edit e =
      test::replace_rhs(preset_text("tof-spad"), "spad", "dead_time_s", R"({ value = nan, source = "assumed: test" })");
  expect_load_error(e, {true, key, range_of("tof-spad", key), {"nan"}});
}

TEST(PresetErrors, Infinity) {
  const std::string key = "source.pulse_width_s";
  const Edit e = test::replace_rhs(preset_text("tof-lockin"), "source", "pulse_width_s",
                                   R"({ value = inf, source = "assumed: test" })");
  expect_load_error(e, {true, key, range_of("tof-lockin", key), {"inf"}});
}

TEST(PresetErrors, ZeroTime) {
  const std::string key = "suppression.lpf_time_constant_s";
  const Edit e = test::replace_rhs(preset_text("ls-demodulation"), "suppression", "lpf_time_constant_s",
                                   R"({ value = 0.0, source = "assumed: test" })");
  expect_load_error(e, {true, key, range_of("ls-demodulation", key), {"out of range"}});
}

TEST(PresetErrors, OutOfRangeInteger) {
  const std::string key = "pixel.columns";
  const Edit e = test::replace_rhs(preset_text("ls-demodulation"), "pixel", "columns",
                                   R"({ value = 100000, source = "assumed: test" })");
  expect_load_error(e, {true, key, range_of("ls-demodulation", key), {"100000", "out of range"}});
}

TEST(PresetErrors, OutOfRangeIntegerBelowMinimum) {
  const std::string key = "tdc.columns_per_tdc";
  const Edit e = test::replace_rhs(preset_text("tof-spad"), "tdc", "columns_per_tdc",
                                   R"({ value = -4, source = "assumed: test" })");
  expect_load_error(e, {true, key, range_of("tof-spad", key), {"out of range"}});
}

TEST(PresetErrors, OutOfRangeReal) {
  const std::string key = "source.duty_cycle";
  const Edit e = test::replace_rhs(preset_text("tof-lockin"), "source", "duty_cycle",
                                   R"({ value = 0.6, source = "assumed: test" })");
  expect_load_error(e, {true, key, range_of("tof-lockin", key), {"0.6", "out of range"}});
}

// ---- Malformed entries. ----

// A plain value is a user's edit (presets that inherit give only what they change): it loads, with
// source "user"; an inline table needs both fields.
TEST(PresetErrors, PlainValueIsAUserEditAndATableNeedsBothFields) {
  const Edit e = test::replace_rhs(preset_text("tof-lockin"), "source", "duty_cycle", "0.1");
  const ParamSet p = load_preset_text(e.text, "plain.toml");
  EXPECT_DOUBLE_EQ(p.real("source.duty_cycle"), 0.1);
  EXPECT_EQ(p.at("source.duty_cycle").source, "user");
  EXPECT_EQ(p.at("source.duty_cycle").file, "plain.toml");
  const Edit t = test::replace_rhs(preset_text("tof-lockin"), "source", "duty_cycle", "{ source = \"x\" }");
  expect_load_error(t, {true, "source.duty_cycle", "", {"value", "source"}});
}

TEST(PresetErrors, MissingSource) {
  const std::string key = "spad.pde";
  const Edit e = test::replace_rhs(preset_text("tof-spad"), "spad", "pde", "{ value = 0.2 }");
  expect_load_error(e, {true, key, "", {"source"}});
}

TEST(PresetErrors, EmptySource) {
  const std::string key = "spad.pde";
  const Edit e = test::replace_rhs(preset_text("tof-spad"), "spad", "pde", R"({ value = 0.2, source = "" })");
  expect_load_error(e, {true, key, "", {"source"}});
}

TEST(PresetErrors, UnknownField) {
  const std::string key = "pixel.fd1_capacitance_F";
  const Edit e = test::replace_rhs(preset_text("tof-lockin"), "pixel", "fd1_capacitance_F",
                                   R"({ value = 10e-15, source = "published: x", unit = "F" })");
  expect_load_error(e, {true, key, "", {"unit"}});
}

// ---- File-level errors. ----

TEST(PresetErrors, UnknownSensorId) {
  const Edit e = test::replace_line(preset_text("tof-spad"), "sensor", "id", R"(id = "tof-flash")");
  // The loader does not know the line of a string value; it names the file.
  expect_load_error(
      e, {false, "sensor.id", "", {"tof-flash", "ls-conventional", "ls-demodulation", "tof-lockin", "tof-spad"}});
}

TEST(PresetErrors, MissingSensorId) {
  const Edit e = test::delete_line(preset_text("ls-demodulation"), "sensor", "id");
  expect_load_error(e, {false, "sensor.id", "", {"tof-lockin"}});
}

TEST(PresetErrors, TomlSyntaxError) {
  const Edit e =
      test::replace_rhs(preset_text("tof-lockin"), "gates", "clock_Hz", R"({ value = 100e6, source = "unterminated )");
  expect_load_error(e, {true, "", "", {"TOML syntax error"}});
}

TEST(PresetErrors, NonexistentFile) {
  const std::string path = "/nonexistent-rangesim-dir/no-such-preset.toml";
  const std::string direct = user_error_of([&] { load_preset_file(path); });
  EXPECT_NE(direct.find(path), std::string::npos) << direct;
  EXPECT_NE(direct.find("cannot read"), std::string::npos) << direct;
  const std::string resolved = user_error_of([&] { load_preset(path); });
  EXPECT_NE(resolved.find(path), std::string::npos) << resolved;
}

TEST(PresetErrors, UnreadableFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "root reads files regardless of permissions";
  TempPreset file(preset_text("tof-spad"));
  std::filesystem::permissions(file.path(), std::filesystem::perms::none);
  const std::string msg = user_error_of([&] { load_preset_file(file.path()); });
  EXPECT_NE(msg.find(file.path()), std::string::npos) << msg;
  EXPECT_NE(msg.find("cannot read"), std::string::npos) << msg;
}

TEST(PresetErrors, PathThroughAFileIsUnreadable) {
  // Readable by nobody, root included: a path whose parent is a regular file.
  TempPreset file(preset_text("tof-spad"));
  const std::string path = file.path() + "/inner.toml";
  const std::string msg = user_error_of([&] { load_preset_file(path); });
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  EXPECT_NE(msg.find("cannot read"), std::string::npos) << msg;
}

TEST(PresetErrors, DirectoryGivenToLoadPresetFile) {
  TempPreset file(preset_text("tof-spad"));
  const std::string msg = user_error_of([&] { load_preset_file(file.dir()); });
  EXPECT_NE(msg.find(file.dir()), std::string::npos) << msg;
}

TEST(PresetErrors, DirectoryInsteadOfFile) {
  TempPreset file(preset_text("tof-spad"));
  const std::string msg = user_error_of([&] { load_preset(file.dir() + "/"); });
  EXPECT_NE(msg.find(file.dir()), std::string::npos) << msg;
}

TEST(PresetErrors, UnknownPresetId) {
  const std::string msg = user_error_of([] { load_preset("tof-flash"); });
  EXPECT_NE(msg.find("tof-flash"), std::string::npos) << msg;
  for (const auto& id : test::preset_ids()) EXPECT_NE(msg.find(id), std::string::npos) << msg;
}

// ---- Command-line overrides are checked against the same ranges. ----

TEST(PresetErrors, IntegerOverrideOutOfRangeNamesFlagKeyAndRange) {
  ParamSet set = load_preset("tof-spad");
  const ParamSchema& schema = tof_spad_schema();
  const std::string msg = user_error_of([&] { set.set_integer("tdc.bits", 0, "--tdc-bits", schema); });
  EXPECT_NE(msg.find("--tdc-bits"), std::string::npos) << msg;
  EXPECT_NE(msg.find("tdc.bits"), std::string::npos) << msg;
  EXPECT_NE(msg.find(range_of("tof-spad", "tdc.bits")), std::string::npos) << msg;
  set.set_integer("tdc.bits", 12, "--tdc-bits", schema);
  EXPECT_EQ(set.integer("tdc.bits"), 12);
  EXPECT_EQ(user_error_of([&] { set.set_integer("tdc.nope", 1, "--x", schema); }).find("tdc.nope") != std::string::npos,
            true);
}

// ---- Stricter messages: an unknown key lists the allowed keys of its section, a plain value
// gives the allowed range, a directory is reported as unreadable. ----

TEST(PresetErrors, UnknownKeyListsAllowedKeys) {
  const Edit e = test::insert_after_header(preset_text("ls-demodulation"), "pixel",
                                           R"(bogus_gain = { value = 1.0, source = "assumed: test" })");
  expect_load_error(e, {true, "pixel.bogus_gain", "", {"pixel.columns", "pixel.integration_time_s"}});
}

TEST(PresetErrors, DirectoryGivenToLoadPresetFileCannotBeRead) {
  TempPreset file(preset_text("tof-spad"));
  const std::string msg = user_error_of([&] { load_preset_file(file.dir()); });
  EXPECT_NE(msg.find("cannot read"), std::string::npos) << msg;
}

TEST(PresetErrors, PlainValueOutOfRangeGivesTheRange) {
  const std::string key = "source.duty_cycle";
  const Edit e = test::replace_rhs(preset_text("tof-lockin"), "source", "duty_cycle", "0.9");
  expect_load_error(e, {true, key, range_of("tof-lockin", key), {}});
}

}  // namespace
}  // namespace rangesim
