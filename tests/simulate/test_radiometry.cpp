// The radiometry of physical scenes (scene/light.h, scene/physical.h, core/<sensor>/radiometry.cpp)
// against hand calculations with the shipped presets' numbers, worked in docs/radiometry.md; the
// scene keys a sensor cannot use as notes; physical values out of range as errors naming the key
// and the allowed range.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/preset.h"
#include "core/sensor_registry.h"
#include "core/user_error.h"
#include "scene/light.h"
#include "scene/physical.h"
#include "scene/scene.h"

namespace sc = rangesim::scene;

namespace {

const std::string kScenes = RANGESIM_SCENE_DIR;

rangesim::SensorRadiometry radiometry(const std::string& id) {
  return rangesim::radiometry_for(rangesim::load_preset(id), id);
}

// 1 W/m2/nm flat ambient light through a 10 nm filter (10 W/m2 in band) on a 50% wall at 1 m, and a
// 1 W source: the conditions of the hand calculations.
std::string hand_scene(const std::string& beam, const std::string& extra = "") {
  return "[scene]\nname = \"hand\"\n[target]\nshape = \"plane\"\ndistance_m = 1.0\nreflectance = 0.5\n"
         "[ambient]\nspectral_irradiance_W_per_m2_nm = 1.0\n[source]\npower_W = 1.0\nbeam = \"" +
         beam + "\"\n[camera]\nfilter_bandwidth_m = 10e-9\n" + extra;
}

sc::NativeLight native(const std::string& sensor, const std::string& beam, const std::string& extra = "") {
  const sc::Scene s = sc::load_scene_text(hand_scene(beam, extra), "hand.toml", sensor);
  return sc::native_light(s, radiometry(sensor));
}

std::string error_of(const std::string& text, const std::string& sensor) {
  try {
    const sc::Scene s = sc::load_scene_text(text, "bad.toml", sensor);
    (void)sc::native_light(s, radiometry(sensor));
  } catch (const rangesim::UserError& e) {
    return e.what();
  }
  return "";
}

void expect_rel(double got, double want, double rel = 1e-9) { EXPECT_NEAR(got, want, std::abs(want) * rel) << got; }

}  // namespace

// Photometry: the spectrum's illuminance comes back from the spectral irradiance (683 lm/W x the
// integral of V E), and sunlight is a 5778 K black body: ~93 lm/W (94.4 with this V(lambda)), and
// 100 klux give 0.82 W/m2/nm at 850 nm (the AM1.5 standard spectrum: about 0.9 at 110 klux).
TEST(Radiometry, LuxAndSpectraByHand) {
  for (const auto& name : sc::spectrum_names()) {
    double lux = 0;
    for (int nm = 360; nm <= 830; ++nm)
      lux += (nm == 360 || nm == 830 ? 0.5 : 1.0) * sc::kLumensPerWatt * sc::photopic_luminosity(nm * 1e-9) *
             sc::spectral_irradiance_W_per_m2_nm(name, 1000.0, nm * 1e-9);
    EXPECT_NEAR(lux, 1000.0, 1e-9) << name;
  }
  EXPECT_NEAR(sc::luminous_efficacy_lm_per_W("sunlight"), 94.35, 0.05);
  EXPECT_NEAR(sc::spectral_irradiance_W_per_m2_nm("sunlight", 1e5, 850e-9), 0.8167, 0.001);
  EXPECT_NEAR(sc::spectral_irradiance_W_per_m2_nm("halogen", 1e5, 850e-9), 3.662, 0.005);
  // A white LED has no near infrared: nothing for a narrow-band sensor at 850 nm.
  EXPECT_LT(sc::spectral_irradiance_W_per_m2_nm("led", 1e5, 850e-9), 1e-6);
  EXPECT_NEAR(sc::photopic_luminosity(555e-9), 1.0, 0.02);
}

// ls-conventional: P_bg = 0.5 x 10 W/m2 / (4 x 1.4^2) x (11.25 um)^2 x 0.5 = 4.0358e-11 W;
// V = R P t / C = 0.4 x P x 50 us / 40 fF = 5e8 V/W x P = 0.020179 V. Sheet peak:
// 0.5 x 1 W x (10 mm)^2 x 0.5 / (4 x 1.96 x 365 rows x 1.27398 px x sqrt(2 pi)) = 2.7358e-9 W -> 1.3679 V.
TEST(Radiometry, LsConventionalByHand) {
  const sc::NativeLight n = native("ls-conventional", "sheet");
  EXPECT_EQ(n.unit, "V");
  expect_rel(n.ambient_in_band_W_per_m2, 10.0);
  expect_rel(n.background, 0.02017897002551021);
  expect_rel(n.signal_at(1.0), 1.367878807164482);
  expect_rel(native("ls-conventional", "sheet", "").signal_at(2.0), 1.367878807164482 / 4);
}

// ls-demodulation: P_bg = 0.6378 x (45 um)^2 x 0.25 = 3.2286e-10 W, I = 0.4 A/W x P = 1.2915e-10 A.
// Sheet peak 0.5 x (25 mm)^2 x 0.25 / (7.84 x 110 x 1.27398 x 2.5066) = 2.8368e-8 W, beam-on
// current 0.4 x P / 0.5 (duty) = 2.2694e-8 A.
TEST(Radiometry, LsDemodulationByHand) {
  const sc::NativeLight n = native("ls-demodulation", "sheet");
  EXPECT_EQ(n.unit, "A");
  expect_rel(n.background, 1.2914540816326534e-10);
  expect_rel(n.signal_at(1.0), 2.2694352937047097e-08);
}

// tof-lockin: P_bg = 0.6378 x (15 um)^2 x 0.2 = 2.8699e-11 W, I = 0.3 A/W x P = 8.6097e-12 A. A
// flood over the field of view: 0.5 x (8 mm)^2 x 0.2 / (7.84 x 336 x 252) = 9.6410e-12 W, during
// the pulse 0.3 x P / 0.1 (duty) = 2.8923e-11 A. A sheet is seen as the same flood.
TEST(Radiometry, TofLockinByHand) {
  const sc::NativeLight n = native("tof-lockin", "flood");
  EXPECT_EQ(n.unit, "A");
  expect_rel(n.background, 8.609693877551022e-12);
  expect_rel(n.signal_at(1.0), 2.8923133879402096e-11);
  expect_rel(native("tof-lockin", "sheet").signal_at(1.0), 2.8923133879402096e-11);
}

// tof-spad: P_bg = 0.6378 x (25 um)^2 x 0.06 = 2.3916e-11 W; a photon at 635 nm is 3.1283e-19 J, so
// n = 0.2 x P / 3.1283e-19 J = 1.5290e7 Hz. Flood: 0.5 x (8 mm)^2 x 0.06 / (7.84 x 128 x 128) =
// 1.4947e-11 W -> 9.5564e6 Hz; an 8 x 8 pixel spot: the same power on 64 pixels, 2.4464e9 Hz.
TEST(Radiometry, TofSpadByHand) {
  const sc::NativeLight n = native("tof-spad", "flood");
  EXPECT_EQ(n.unit, "Hz");
  expect_rel(n.background, 15290165.913853418);
  expect_rel(n.signal_at(1.0), 9556353.696158385);
  const sc::NativeLight spot = native("tof-spad", "spot", "[beam]\nrows = 8\ncolumns = 8\n");
  expect_rel(spot.signal_at(1.0), 2446426546.2165465);
  EXPECT_EQ(spot.spot_first_row, 60);
  EXPECT_EQ(spot.spot_first_column, 60);
}

// Lux through the chain: 100 klux of sunlight at 850 nm on ls-conventional, 10 nm filter:
// 0.8167 W/m2/nm x 10 nm = 8.167 W/m2 -> 0.8167 x 0.020179 V = 0.016480 V.
TEST(Radiometry, LuxAxisIsLinear) {
  const std::string text =
      "[scene]\nname = \"lux\"\n[target]\ndistance_m = 1.0\nreflectance = 0.5\n[ambient]\nilluminance_lux = 1e5\n"
      "[source]\npower_W = 1.0\nwavelength_m = 850e-9\n[camera]\nfilter_bandwidth_m = 10e-9\n";
  const sc::Scene s = sc::load_scene_text(text, "lux.toml", "ls-conventional");
  const auto r = radiometry("ls-conventional");
  const double per_lux = sc::native_background_per_lux(s, r);
  EXPECT_NEAR(sc::native_light(s, r).background, 0.016480, 2e-5);
  expect_rel(per_lux * 1e5, sc::native_light(s, r).background);
  expect_rel(sc::native_signal_per_W(s, r, 1.0), 1.367878807164482);
}

// A key another sensor uses is a note, not an error; every example scene loads for every sensor.
TEST(Radiometry, OtherSensorsKeysAreNotes) {
  const sc::Scene s = sc::load_scene(kScenes + "/tof-spad-plane.toml", "ls-conventional");
  bool noted = false;
  for (const auto& n : s.notes) noted = noted || n.find("rates.signal_Hz is not used by ls-conventional") != std::string::npos;
  EXPECT_TRUE(noted);
  EXPECT_TRUE(s.light.present);
  for (const char* name : {"plane", "tilted", "step", "depth-map", "sunlit-wall", "ls-demodulation-plane",
                           "ls-demodulation-depth-map", "tof-lockin-plane", "tof-lockin-step", "tof-lockin-depth-map",
                           "tof-spad-plane", "tof-spad-step", "tof-spad-depth-map", "tof-spad-spot", "objects"})
    for (const auto& sensor : rangesim::sensors()) {
      const sc::Scene x = sc::load_scene(kScenes + "/" + name + ".toml", sensor.id);
      EXPECT_TRUE(x.light.present) << name << " " << sensor.id;
      EXPECT_NO_THROW((void)sc::native_light(x, radiometry(sensor.id))) << name << " " << sensor.id;
    }
}

// Physical values out of range: the error names the key and its range.
TEST(Radiometry, OutOfRangeValuesNameKeyAndRange) {
  std::string t = hand_scene("sheet");
  t.replace(t.find("reflectance = 0.5"), 17, "reflectance = -0.2");
  std::string e = error_of(t, "tof-lockin");
  EXPECT_NE(e.find("target.reflectance = -0.2 is out of range; allowed: (0, 1]"), std::string::npos) << e;
  t = hand_scene("sheet");
  t.replace(t.find("spectral_irradiance_W_per_m2_nm = 1.0"), 37, "illuminance_lux = -5");
  e = error_of(t, "tof-spad");
  EXPECT_NE(e.find("ambient.illuminance_lux = -5 is out of range; allowed: [0, 1e+06]"), std::string::npos) << e;
  e = error_of(hand_scene("spot", "[beam]\nfirst_row = 125\nrows = 8\n"), "tof-spad");
  EXPECT_NE(e.find("beam.first_row = 125 puts the spot outside the 128 x 128 array"), std::string::npos) << e;
  EXPECT_NE(e.find("allowed 0 <= value <= 120"), std::string::npos) << e;
  e = error_of(hand_scene("spot", "[beam]\nrows = 300\n"), "tof-lockin");
  EXPECT_NE(e.find("beam.rows = 300"), std::string::npos) << e;
  t = hand_scene("laser");
  e = error_of(t, "ls-conventional");
  EXPECT_NE(e.find("source.beam = \"laser\"; allowed: \"sheet\", \"flood\", \"spot\""), std::string::npos) << e;
  t = hand_scene("sheet") + "";
  t.replace(t.find("spectral_irradiance_W_per_m2_nm = 1.0"), 37, "illuminance_lux = 5\nspectrum = \"neon\"");
  e = error_of(t, "ls-demodulation");
  EXPECT_NE(e.find("ambient.spectrum = \"neon\" is not a known spectrum; allowed: \"sunlight\", \"halogen\", \"led\""),
            std::string::npos)
      << e;
}

// Several objects: rasterised at a sensor's grid, the nearest face wins; bad tables name the key.
TEST(Radiometry, ObjectsRasterise) {
  const sc::Scene s = sc::load_scene(kScenes + "/objects.toml", "tof-spad");
  ASSERT_EQ(s.objects.size(), 2U);
  const std::vector<double> z = sc::depth_grid_m(s, 10, 20, 25e-6, 8e-3);
  EXPECT_DOUBLE_EQ(z[0], 1.2);                 // row 0, column 0: the wall
  EXPECT_DOUBLE_EQ(z[4 * 20 + 5], 0.9);        // row 4 (v = 0.45), column 5 (u = 0.275): the first box
  EXPECT_DOUBLE_EQ(z[6 * 20 + 13], 1.0);       // row 6 (v = 0.65), column 13 (u = 0.675): the second box
  std::string t = "[scene]\nname = \"o\"\n[target]\nshape = \"objects\"\ndistance_m = 2\n[[object]]\ndistance_m = 1\n"
                  "left = 0.6\nright = 0.2\n[source]\npower_W = 1\n";
  std::string e = error_of(t, "ls-demodulation");
  EXPECT_NE(e.find("left < right"), std::string::npos) << e;
  t = "[scene]\nname = \"o\"\n[target]\nshape = \"objects\"\ndistance_m = 2\n[[object]]\ndistance_m = -1\n"
      "[source]\npower_W = 1\n";
  e = error_of(t, "tof-lockin");
  EXPECT_NE(e.find("object.distance_m must be a number in [0.01, 10000] m"), std::string::npos) << e;
}
