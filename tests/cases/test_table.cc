// The table writer (cases/report/table.h): one column spec, from which the CSV and the Markdown of a table are
// written; the quoting and escaping rules of the two files; the writing of report files.
#include "scene_files.h"

#include <cases/report/table.h>

#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>

using namespace gradcontact::cases;
namespace fs = std::filesystem;
using testing::TemporaryFolder;

namespace
{
  std::string read(const fs::path &file)
  {
    std::ifstream in(file);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
} // namespace

TEST_CASE("A table shall write its CSV and its Markdown from one column spec", "[cases][quick]")
{
  Table table({Column::csv_only("k"), Column::both("ratio", "a/z0"), Column::both("force_deviation", "force"),
               Column::md_only("F / F_0"), Column::both("dofs", "DoFs"), Column::csv_only("error").quoted()},
              Number{'g', 10});
  table.add({0.5, 100., 0.0123456789012, 1.0123456789012, 4321u, ""});
  table.add({-0.5, std::numeric_limits<double>::infinity(), Cell(0.).md_text("failed: no contact"),
             Cell(1.).md_text("-"), 12, "no contact"});
  CHECK(table.size() == 2);
  CHECK(table.csv() == "k,ratio,force_deviation,dofs,error\n"
                       "0.5,100,0.0123456789,4321,\"\"\n"
                       "-0.5,inf,0,12,\"no contact\"\n");
  CHECK(table.md() == "| a/z0 | force | F / F_0 | DoFs |\n"
                      "|---|---|---|---|\n"
                      "| 100 | 0.0123457 | 1.01235 | 4321 |\n"
                      "| inf | failed: no contact | - | 12 |\n");
}

TEST_CASE("A table's number formats shall be those of printf, per file and per column", "[cases][quick]")
{
  // %.6g is what a stream writes at its default precision: format() and the tables agree with the files before them
  std::ostringstream stream;
  stream << 1.0 / 3 << ' ' << 12345678.9 << ' ' << 1e-300;
  CHECK(format(1.0 / 3, Number{}) + ' ' + format(12345678.9, Number{}) + ' ' + format(1e-300, Number{}) ==
        stream.str());
  CHECK(format(2.5e-7, Number{'e', 1}) == "2.5e-07");
  CHECK(format(1e300, Number{'f', 2}).size() == 304); // longer than any fixed buffer
  CHECK_THROWS_AS(format(1., Number{'x', 3}), std::invalid_argument);

  Table table({Column::both("seconds", "s").md_as(Number{'f', 3}), Column::csv_only("nu").csv_as(Number{'f', 6})},
              Number{'g', 17});
  table.add({0.1, 0.3});
  CHECK(table.csv() == "seconds,nu\n0.10000000000000001,0.300000\n");
  CHECK(table.md() == "| s |\n|---|\n| 0.100 |\n");
}

TEST_CASE("A table shall quote CSV texts, escape | in Markdown cells and show missing cells", "[cases][quick]")
{
  Table table({Column::both("quantity", "quantity").quoted(), Column::both("metric", "metric"),
               Column::both("stick", "c/a").missing_as("- (no contact)"), Column::both("note", "note")});
  table.add({"p(r) \"max\"", "|F_c / F_JKR - 1|", Cell(), ""});
  CAPTURE(table.csv(), table.md());
  CHECK(table.csv() == "quantity,metric,stick,note\n\"p(r) \"\"max\"\"\",|F_c / F_JKR - 1|,,\n");
  CHECK(table.md() == "| quantity | metric | c/a | note |\n|---|---|---|---|\n"
                      "| p(r) \"max\" | \\|F_c / F_JKR - 1\\| | - (no contact) |  |\n");
}

TEST_CASE("A row of another count of cells than the table's columns shall be refused", "[cases][quick]")
{
  Table table({Column::both("a", "a"), Column::both("b", "b")});
  CHECK_THROWS_WITH(table.add({1., 2., 3.}), Catch::Contains("a row of 3 cells in a table of 2 columns"));
  CHECK_THROWS_AS(table.append(Table({Column::csv_only("a")})), std::invalid_argument);
  Table more({Column::both("a", "a"), Column::both("b", "b")});
  more.add({1, 2});
  table.append(more);
  table.append(more);
  CHECK(table.csv() == "a,b\n1,2\n1,2\n");
}

TEST_CASE("A table declared by fields shall take each cell from its row", "[cases][quick]")
{
  struct Point
  {
    double x, y;
  };
  const std::vector<Field<Point>> fields{{Column::both("x", "x"), [](const Point &p) { return Cell(p.x); }},
                                         {Column::csv_only("y"), [](const Point &p) { return Cell(p.y); }}};
  CHECK(tabulate(fields, std::vector<Point>{{1, 2}, {3, 4}}).csv() == "x,y\n1,2\n3,4\n");
}

TEST_CASE("A report file shall be written whole, and an unwritable one shall be an error naming it", "[cases][quick]")
{
  const TemporaryFolder folder("gradcontact-table");
  const fs::path file = folder.path() / "summary.md";
  write_text_atomically(file, "# old\n");
  write_text_atomically(file, "# new\n");
  CHECK(read(file) == "# new\n");
  std::size_t entries = 0;
  for (const auto &e : fs::directory_iterator(folder.path()))
    entries += e.is_regular_file();
  CHECK(entries == 1); // no temporary left
  CHECK_THROWS_WITH(write_text(folder.path() / "missing" / "errors.csv", "x"),
                    Catch::Contains("cannot write") && Catch::Contains("missing/errors.csv"));
}
