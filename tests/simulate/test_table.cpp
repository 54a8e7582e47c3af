// The CSV number text of simulate's tables (systemc/common/table.h): std::to_chars must print
// exactly what printf "%.9g" (fmt "{:.9g}", the format before it) printed, so the CSV files stay
// byte-identical; NaN and inf are empty cells; integer columns print as integers.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "systemc/common/table.h"

namespace rs = rangesim::systemc;

TEST(CsvNumber, SameTextAsPrintfG9) {
  std::mt19937_64 g(12345);
  std::uniform_real_distribution<double> mant(-1.0, 1.0);
  std::uniform_int_distribution<int> ex(-320, 308);
  std::vector<double> values = {0.0, -0.0, 1.0, 0.1, 1e-5, 1e-4, 123456789.0, 1234567890.0, 1e16, 5e-324,
                                std::numeric_limits<double>::max(), 0.5, 2.5, 0.999999999, 9.9999999995};
  for (int i = 0; i < 200000; ++i) values.push_back(mant(g) * std::pow(10.0, ex(g) % 40));
  for (int i = 0; i < 20000; ++i) values.push_back(std::ldexp(mant(g), ex(g) * 3));
  for (double v : values) {
    std::string s;
    rs::append_csv_number(s, v);
    ASSERT_EQ(s, fmt::format("{:.9g}", v)) << v;
  }
  std::string s;
  rs::append_csv_number(s, NAN);
  rs::append_csv_number(s, INFINITY);
  EXPECT_EQ(s, "");
}

TEST(CsvNumber, TableCsv) {
  rs::Table t({{"frame", rs::Table::Kind::Index}, {"range_m"}});
  t.add_row({3, 0.125});
  t.add_row({4, NAN});
  t.add_row({-5, 1.0 / 3});
  EXPECT_EQ(t.rows(), 3U);
  EXPECT_EQ(rs::table_csv(t), "frame,range_m\n3,0.125\n4,\n-5,0.333333333\n");
}
