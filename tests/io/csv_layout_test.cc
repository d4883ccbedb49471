#include "vantage/io/csv_layout.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"

namespace vantage::io {
namespace {

// Decimal numbers are read with correct rounding: the file and this literal give the same double.
constexpr double kExact = 0.0;

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;

std::string csv_error_of(const std::string& text) {
  try {
    parse_csv_layout(text, "bad.csv");
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
}

struct BadCsv {
  const char* name;
  const char* text;
  const char* expected;  // the line and column the one error line must name
};

class BadCsvFile : public ::testing::TestWithParam<BadCsv> {};

TEST_P(BadCsvFile, GivesOneLineNamingFileLineAndColumn) {
  const std::string message = csv_error_of(GetParam().text);
  ASSERT_FALSE(message.empty()) << "accepted: " << GetParam().text;
  EXPECT_THAT(message, HasSubstr("bad.csv: "));
  EXPECT_THAT(message, HasSubstr(GetParam().expected));
  EXPECT_THAT(message, Not(HasSubstr("\n")));
}

const BadCsv kBadCsvs[] = {
    {"Empty", "", "no marker rows"},
    {"OnlyComments", "# nothing\n\n# here\n", "no marker rows"},
    {"OnlyHeader", "name,x,y,z\n", "no marker rows after the header"},
    {"ThreeFields", "a,0,0\nb,1,0\nc,0,1\n", "line 1: expected 4, 5, 7 or 8 fields"},
    {"SixFields", "a,0,0,0,1,9\n", "line 1: expected 4, 5, 7 or 8 fields"},
    {"ZeroNormal", "a,0,0,0,0,0,1\nb,1,0,0,0,0,0\nc,0,1,0,0,0,1\n",
     "line 2 (b), nx,ny,nz: zero length"},
    {"NormalNotANumber", "a,0,0,0,1,0,0,1\nb,1,0,0,1,0,x,0\nc,0,1,0,1,0,0,1\n",
     "line 2 (b), ny: expected a finite number"},
    {"HeaderMisnamesNormals", "name,x,y,z,w,nx,ny,nz\na,0,0,0,1,0,0,1\nb,1,0,0,1,0,0,1\n",
     "line 1: column 5 of the header is \"w\", expected \"weight\""},
    {"RaggedRow", "a,0,0,0\nb,1,0,0,2\nc,0,1,0\n", "line 2 (b): expected 4 fields like the first"},
    {"TypoInTheFirstRow", "a,0,O,0\nb,1,0,0\nc,0,1,0\nd,1,1,1\n",
     "line 1 (a), y: expected a finite number, got \"O\""},
    {"NotANumber", "a,0,0,0\nb,1,zero,0\nc,0,1,0\n", "line 2 (b), y: expected a finite number"},
    {"EmptyNumber", "a,0,0,0\nb,1,,0\nc,0,1,0\n", "line 2 (b), y: expected a finite number"},
    {"NaN", "a,0,0,0\nb,1,0,nan\nc,0,1,0\n", "line 2 (b), z: expected a finite number"},
    {"Overflow", "a,0,0,0\nb,1e999,0,0\nc,0,1,0\n", "line 2 (b), x: expected a finite number"},
    {"TrailingJunk", "a,0,0,0\nb,1m,0,0\nc,0,1,0\n", "line 2 (b), x: expected a finite number"},
    {"EmptyName", "a,0,0,0\n,1,0,0\nc,0,1,0\n", "line 2, name: empty marker name"},
    {"RepeatedName", "a,0,0,0\nb,1,0,0\na,0,1,0\n",
     "line 3 (a), name: repeats the marker of line 1"},
    {"ZeroWeight", "# c\nname,x,y,z,weight\na,0,0,0,1\nb,1,0,0,0\nc,0,1,0,1\n",
     "line 4 (b), weight: must be > 0"},
    {"NegativeWeight", "a,0,0,0,-2\nb,1,0,0,1\nc,0,1,0,1\n", "line 1 (a), weight: must be > 0"},
    {"CoincidentMarkers", "a,0,0,0\nb,1,0,0\nc,1,0,0\n", "line 3 (c): coincides with line 2 (b)"},
    {"TwoMarkers", "a,0,0,0\nb,1,0,0\n", "points: need at least 3 points"},
    // Issue 22: a first row of missing values was taken for a header and silently dropped.
    {"NanFirstRow", "m1,nan,nan,nan\nm2,0,0,0\nm3,1,0,0\nm4,0,1,0\nm5,0,0,1\n",
     "line 1 (m1), x: expected a finite number, got \"nan\""},
    {"NotAvailableFirstRow", "m1,n/a,n/a,n/a\nm2,0,0,0\nm3,1,0,0\nm4,0,1,0\nm5,0,0,1\n",
     "line 1 (m1), x: expected a finite number, got \"n/a\""},
    {"EmptyFirstRow", "m1,,,\nm2,0,0,0\nm3,1,0,0\nm4,0,1,0\n",
     "line 1 (m1), x: expected a finite number, got \"\""},
    {"InfinityFirstRow", "m1,inf,-inf,0\nm2,0,0,0\nm3,1,0,0\nm4,0,1,0\n",
     "line 1 (m1), x: expected a finite number, got \"inf\""},
    {"NullWeightFirstRow", "m1,0,0,0,NULL\nm2,1,0,0,1\nm3,0,1,0,1\n",
     "line 1 (m1), weight: expected a finite number, got \"NULL\""},
    {"InfinityInData", "a,0,0,0\nb,Infinity,0,0\nc,0,1,0\n", "line 2 (b), x: expected a finite"},
};

INSTANTIATE_TEST_SUITE_P(CsvLayout, BadCsvFile, ::testing::ValuesIn(kBadCsvs),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(CsvLayout, ReadsMarkersWithoutHeaderOrWeights) {
  const CsvMarkers m = parse_csv_markers("a,0,0,0\nb,1,0,0\nc,0,2,0.5\n", "dir/body.csv");
  EXPECT_EQ(m.layout.mode, LayoutMode::kPoints);
  EXPECT_EQ(m.layout.name, "body");
  EXPECT_THAT(m.names, ElementsAre("a", "b", "c"));
  Eigen::Matrix3Xd expected(3, 3);
  expected << 0, 1, 0, 0, 0, 2, 0, 0, 0.5;
  EXPECT_EIGEN_NEAR(m.layout.entries, expected, kExact);
  EXPECT_EIGEN_NEAR(m.layout.weights, Eigen::VectorXd::Ones(3), kExact);
  EXPECT_EQ(m.layout.candidates.cols(), 0);
}

TEST(CsvLayout, HeaderIsDecidedByItsCells) {
  // No cell after the name holds a value: a header, whatever its words.
  const CsvMarkers m =
      parse_csv_markers("Marker,X (m),Y (m),Z (m)\na,0,0,0\nb,1,0,0\nc,0,1,0\n", "h.csv");
  EXPECT_THAT(m.names, ElementsAre("a", "b", "c"));
  // One coordinate that holds a value (a number, NaN, empty, n/a) makes the row data.
  EXPECT_THAT(csv_error_of("name,x,0,z\na,0,0,0\nb,1,0,0\nc,0,1,0\n"),
              HasSubstr("line 1 (name), x: expected a finite number"));
  EXPECT_THAT(csv_error_of("name,NA,y,z\na,0,0,0\nb,1,0,0\nc,0,1,0\n"),
              HasSubstr("line 1 (name), x: expected a finite number, got \"NA\""));
}

TEST(CsvLayout, HeaderCommentsBlanksQuotesCrlfAndBomAreTolerated) {
  const std::string text =
      "\xEF\xBB\xBF# exported by a tracker\r\n"
      "Name, X, Y, Z, Weight\r\n"
      "\r\n"
      "\"m 1\", 1.5 , -2, 3e-1, 2\r\n"
      "   # a comment between rows\r\n"
      "m2,0,0,0,0.5\r\n"
      "m3,0,1,0,1";
  const CsvMarkers m = parse_csv_markers(text, "t.csv");
  EXPECT_THAT(m.names, ElementsAre("m 1", "m2", "m3"));
  EXPECT_EIGEN_NEAR(m.layout.entries.col(0), Eigen::Vector3d(1.5, -2, 0.3), kExact);
  EXPECT_EIGEN_NEAR(m.layout.weights, Eigen::Vector3d(2, 0.5, 1), kExact);
}

TEST(CsvLayout, NamesBecomeTheLayoutsNames) {
  const Layout layout =
      parse_csv_layout("name,x,y,z\nLED1,0,0,0\nLED2,1,0,0\nhub,0,1,0\n", "b.csv");
  EXPECT_THAT(layout.names, ElementsAre("LED1", "LED2", "hub"));
}

// Independent truth: the text parse_csv_markers() reads back, compared bit for bit with what was
// written, for values with and without a short decimal form (0.1 prints as 0.1, 1/3 needs 17
// digits); the test checks the reading back, not the digits.
TEST(CsvLayout, WrittenCsvReadsBackExactly) {
  Layout layout;
  layout.name = "body";
  layout.description = "two lines\nof text";
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, 4);
  layout.entries << 0.1, -1.0 / 3.0, 1e-300, 12345.678901234567, 0.2, 2.0 / 7.0, -5e7, 0, 0.3,
      std::nextafter(1.0, 2.0), 4, -0.0;
  layout.weights = Eigen::Vector4d(1, 0.5, 1.0 / 3.0, 7);
  layout.names = {"LED1", "m 2", "tip", "LED:4"};
  const std::string text = layout_to_csv(layout);
  EXPECT_THAT(text, HasSubstr("name,x,y,z,weight\nLED1,0.1,0.2,0.3,1\n"));
  EXPECT_THAT(text, HasSubstr("# name: body\n# description: two lines of text\n"));
  const CsvMarkers again = parse_csv_markers(text, "body.csv");
  EXPECT_TRUE((again.layout.entries.array() == layout.entries.array()).all());
  EXPECT_TRUE((again.layout.weights.array() == layout.weights.array()).all());
  EXPECT_EQ(again.layout.names, layout.names);
  // An unnamed layout's markers are written under the names the rest of vantage shows.
  layout.names.clear();
  EXPECT_THAT(parse_csv_markers(layout_to_csv(layout), "b.csv").layout.names,
              ElementsAre("p0", "p1", "p2", "p3"));
}

// Normals in nx,ny,nz columns (7 fields, or 8 with the weight): normalised on reading, written
// back and read again exactly; the rest of the visibility model has no CSV column.
TEST(CsvLayout, NormalsColumnsReadNormalisedAndWriteBack) {
  const CsvMarkers seven =
      parse_csv_markers("a,0,0,0,0,0,2\nb,1,0,0,3,4,0\nc,0,1,0,0,-1,0\n", "n.csv");
  ASSERT_TRUE(seven.layout.visibility.has_value());
  const Eigen::Matrix3Xd& n = seven.layout.visibility->normals;
  EXPECT_EQ(n.col(0), Eigen::Vector3d(0, 0, 1));
  EXPECT_NEAR((n.col(1) - Eigen::Vector3d(0.6, 0.8, 0)).norm(), 0.0, 1e-15);
  EXPECT_TRUE((seven.layout.weights.array() == 1.0).all());
  EXPECT_TRUE(
      (seven.layout.visibility->cone_half_angle_deg.array() == MarkerVisibility::kDefaultConeDeg)
          .all());
  const CsvMarkers eight = parse_csv_markers(
      "name,x,y,z,weight,nx,ny,nz\na,0,0,0,2,0,0,1\nb,1,0,0,1,1,0,0\nc,0,1,0,1,0,1,0\n", "n.csv");
  EXPECT_EQ(eight.layout.weights(0), 2.0);
  EXPECT_EQ(eight.layout.visibility->normals.col(1), Eigen::Vector3d(1, 0, 0));
  const std::string text = layout_to_csv(seven.layout);
  EXPECT_THAT(text, HasSubstr("name,x,y,z,weight,nx,ny,nz\n"));
  const CsvMarkers again = parse_csv_markers(text, "n.csv");
  EXPECT_TRUE((again.layout.visibility->normals.array() == n.array()).all());
  Layout narrow = seven.layout;
  narrow.visibility->cone_half_angle_deg.setConstant(45.0);
  EXPECT_THROW(layout_to_csv(narrow), InvalidArgument);
}

TEST(CsvLayout, WriterRefusesWhatCsvCannotHold) {
  Layout layout;
  layout.mode = LayoutMode::kPoints;
  layout.entries = Eigen::Matrix3d::Identity();
  layout.weights = Eigen::Vector3d::Ones();
  auto error = [&] {
    try {
      layout_to_csv(layout);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  layout.names = {"a", "b,c", "d"};
  EXPECT_THAT(error(), HasSubstr("names[1]: \"b,c\" contains a comma"));
  layout.names = {"a", "b", " c"};
  EXPECT_THAT(error(), HasSubstr("names[2]"));
  layout.names = {"#a", "b", "c"};
  EXPECT_THAT(error(), HasSubstr("names[0]"));
  layout.names = {"a", "b", "c\"d"};
  EXPECT_THAT(error(), HasSubstr("names[2]"));
  layout.names.clear();
  layout.candidates = Eigen::Vector3d(1, 1, 1);
  EXPECT_THAT(error(), HasSubstr("candidates: a CSV layout cannot hold the 1 candidates"));
  layout.candidates.resize(3, 0);
  layout.mode = LayoutMode::kVectors;
  EXPECT_THAT(error(), HasSubstr("vectors: a CSV layout holds marker positions"));
}

TEST(CsvLayout, ErrorLinesCountCommentsAndBlanks) {
  EXPECT_THAT(csv_error_of("# 1\n\nname,x,y,z\na,0,0,0\nb,0,0,q\n"), HasSubstr("line 5 (b), z"));
}

}  // namespace
}  // namespace vantage::io
