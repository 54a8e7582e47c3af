// The basis of every published figure (golden/common/published_figure.h): what its agreement is
// worth. A calibrated or fitted figure must name a key of its sensor's preset, a fitted one the
// figures the key was fitted to, an arithmetic one the arithmetic. The counts are pinned so that a
// figure changing class (or a new one) is a deliberate edit of this test.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "core/preset.h"
#include "core/sensor_registry.h"
#include "golden/common/evaluate_sensor.h"

namespace rangesim::golden {
namespace {

TEST(PublishedBasis, EveryFigureNamesWhatItRestsOn) {
  std::map<FigureBasis, int> total, reproduced;
  for (const auto& s : sensors()) {
    const GoldenModel* m = golden_model(s.id);
    if (!m || !m->published_figures) continue;
    const ParamSet params = load_preset(s.id);
    const std::vector<PublishedFigure> figs = published_figures(params);
    std::set<std::string> ids;
    for (const auto& f : figs) ids.insert(f.id);
    for (const auto& f : figs) {
      SCOPED_TRACE(s.id + " " + f.id);
      ++total[f.basis];
      reproduced[f.basis] += f.reproduced();
      switch (f.basis) {
        case FigureBasis::Calibrated:
          EXPECT_TRUE(params.has(f.basis_key)) << "calibrated to no preset key: '" << f.basis_key << "'";
          EXPECT_TRUE(f.fitted_to.empty());
          break;
        case FigureBasis::Fitted:
          EXPECT_TRUE(params.has(f.basis_key)) << "fitted key not in the preset: '" << f.basis_key << "'";
          EXPECT_GE(f.fitted_to.size(), 2u);  // one figure would make it calibrated
          for (const auto& id : f.fitted_to) EXPECT_TRUE(ids.count(id)) << "fitted to an unknown figure " << id;
          break;
        case FigureBasis::Arithmetic: EXPECT_FALSE(f.basis_note.empty()) << "arithmetic without saying which"; break;
        case FigureBasis::Predicted: EXPECT_TRUE(f.basis_key.empty()); break;
      }
      EXPECT_GT(f.tolerance, 0.0);
      EXPECT_FALSE(f.basis_text().empty());
    }
  }
  // The account of `table --published` (2026-11-25): of 55 figures only 3 reproduced ones are
  // predictions; the other 28 reproduced ones were tuned to, fitted to, or follow by arithmetic.
  EXPECT_EQ(total[FigureBasis::Calibrated], 10);
  EXPECT_EQ(reproduced[FigureBasis::Calibrated], 10);
  EXPECT_EQ(total[FigureBasis::Fitted], 12);
  EXPECT_EQ(reproduced[FigureBasis::Fitted], 12);
  EXPECT_EQ(total[FigureBasis::Arithmetic], 10);
  EXPECT_EQ(reproduced[FigureBasis::Arithmetic], 6);
  EXPECT_EQ(total[FigureBasis::Predicted], 23);
  EXPECT_EQ(reproduced[FigureBasis::Predicted], 3);
}

TEST(PublishedBasis, SetBasisRefusesAnUnknownFigure) {
  std::vector<PublishedFigure> f{{"s", "a", "d", 1, "1", 1, 0.1, ""}};
  set_basis(f, "a", FigureBasis::Calibrated, "x.y");
  EXPECT_EQ(f[0].basis, FigureBasis::Calibrated);
  EXPECT_EQ(f[0].basis_text(), "calibrated: x.y");
  EXPECT_THROW(set_basis(f, "b", FigureBasis::Predicted), std::logic_error);
}

}  // namespace
}  // namespace rangesim::golden
