// gradcontact/cases: a table written as CSV and as Markdown from one column spec, and the writing of report files.
//
// A report's table is read twice: by a program (the .csv, every digit, plain headers) and by a person (the .md,
// short numbers, readable headers, a dash where a value is missing). Both are written here from one list of
// columns, so that a column added, renamed or dropped changes both files, and the CSV quoting and the Markdown
// escaping are decided in one place rather than in every runner. A column may be in one of the two files only (a
// CSV column of raw inputs, a Markdown column of a ratio made for reading); a cell may show another text in the
// Markdown than its value in the CSV ("failed: ..." where the CSV keeps the number and the error has its own
// column). The parts above report/ build tables and text; the files of a report are written by report/.
#ifndef GRADCONTACT_CASES_TABLE_H
#define GRADCONTACT_CASES_TABLE_H

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace gradcontact::cases
{
  /// How a number is written: printf's %.<digits><style>, style 'g', 'e' or 'f'. The default is format()'s %.6g,
  /// which is also what a C++ stream writes at its default precision.
  struct Number
  {
    char style  = 'g';
    int  digits = 6;
  };

  /// `x` written as `n` says ("nan", "inf" as printf writes them).
  std::string format(double x, Number n);

  /// `text` for a Markdown table cell: a '|' inside it would end the cell, so it is escaped.
  std::string md_escape(const std::string &text);

  /// One column: its header in each file and how its cells are written there.
  class Column
  {
  public:
    /// In both files: `csv` the CSV header (written as given: csv_quote it where it needs quotes), `md` the Markdown
    /// header.
    static Column both(std::string csv, std::string md);
    /// In the CSV only.
    static Column csv_only(std::string csv);
    /// In the Markdown only.
    static Column md_only(std::string md);

    /// Numbers in the CSV written as `n` (default: the table's).
    Column csv_as(Number n) const;
    /// Numbers in the Markdown written as `n` (default: %.6g).
    Column md_as(Number n) const;
    /// Texts in the CSV in double quotes, inner quotes doubled (csv_quote).
    Column quoted() const;
    /// The Markdown of a missing cell (default "-"; in the CSV a missing cell is empty).
    Column missing_as(std::string md) const;

    bool in_csv() const { return !csv_head.empty(); }
    bool in_md() const { return !md_head.empty(); }

    std::string csv_head, md_head;
    std::optional<Number> csv_number;
    Number md_number;
    bool quote = false;
    std::string missing = "-";
  };

  /// One cell: a number, an integer, a text or nothing (missing), and optionally another text in the Markdown.
  class Cell
  {
  public:
    Cell() = default; ///< missing
    Cell(double x);
    Cell(std::string text);
    Cell(const char *text);
    /// Any integer; not bool, which would be written as a number by accident (write it as 0/1 or a word).
    template <class Integer,
              std::enable_if_t<std::is_integral_v<Integer> && !std::is_same_v<Integer, bool>, int> = 0>
    Cell(const Integer n)
      : kind(Kind::integer)
      , integer(static_cast<long long>(n))
    {}
    Cell(bool) = delete;

    /// This cell with `text` in the Markdown in place of its value (escaped like any text); the CSV keeps the value.
    Cell md_text(std::string text) const;

    /// The cell in the CSV of `column`, its numbers written as `number` unless the column says otherwise.
    std::string csv(const Column &column, Number number) const;
    /// The cell in the Markdown of `column`.
    std::string md(const Column &column) const;

  private:
    enum class Kind
    {
      missing,
      number,
      integer,
      text
    };
    Kind kind = Kind::missing;
    double number = 0.;
    long long integer = 0;
    std::string text;
    std::optional<std::string> markdown;
  };

  /// Columns and rows of cells. csv(): the header line and a line per row, fields joined by ','. md(): the header
  /// row, the |---| row and a row per row, each "| a | b |" (an empty cell is "|  |").
  class Table
  {
  public:
    /// `csv_number`: how the CSV writes a number unless its column says otherwise.
    explicit Table(std::vector<Column> columns, Number csv_number = Number{});

    /// Appends a row of one cell per column; throws std::invalid_argument when the count differs.
    void add(std::vector<Cell> row);
    /// Appends the rows of `other`, which has the same columns (e.g. one panel's table into the whole map's).
    void append(const Table &other);
    std::size_t size() const { return rows.size(); }

    std::string csv() const;
    std::string md() const;
    /// csv() into `file` (write_text).
    void write_csv(const std::filesystem::path &file) const;

  private:
    std::vector<Column> columns;
    Number csv_number;
    std::vector<std::vector<Cell>> rows;
  };

  /// A column and how a row of type `Row` fills it: the spec of a table whose rows are values of one type, each column
  /// declared next to what it shows.
  template <class Row>
  struct Field
  {
    Column column;
    std::function<Cell(const Row &)> cell;
  };

  /// The table of `rows` under `fields`.
  template <class Row>
  Table tabulate(const std::vector<Field<Row>> &fields, const std::vector<Row> &rows, const Number csv_number = Number{})
  {
    std::vector<Column> columns;
    for (const Field<Row> &f : fields)
      columns.push_back(f.column);
    Table table(columns, csv_number);
    for (const Row &r : rows)
      {
        std::vector<Cell> cells;
        for (const Field<Row> &f : fields)
          cells.push_back(f.cell(r));
        table.add(std::move(cells));
      }
    return table;
  }

  /// The files of one table of a report in `folder`: <stem>.csv from `table` (every digit, for a program) and <stem>.md,
  /// the document that shows it to a person (`md`: its title, its text and tables' md()), each whole or not at all. The
  /// runners hand their tables and documents here; which files a report has and how they are written is decided in
  /// report/.
  void write_table_files(const std::filesystem::path &folder, const std::string &stem, const Table &table,
                         const std::string &md);
  /// <stem>.csv alone, from `table` (a table that a plot or a program reads, with no document of its own).
  void write_table_csv(const std::filesystem::path &folder, const std::string &stem, const Table &table);
  /// <stem>.md alone: a document whose tables have no CSV of their own (an index, a summary of other reports).
  void write_document(const std::filesystem::path &folder, const std::string &stem, const std::string &md);

  /// Writes `text` into `file`, replacing it; throws std::runtime_error naming the file when it cannot be written.
  /// For a file in a folder that is itself put in place when complete (atomic_folder).
  void write_text(const std::filesystem::path &file, const std::string &text);
  /// The same through a temporary sibling renamed onto `file` when complete: a reader sees the old file or the whole
  /// new one, never a part (a file in a folder that other runs read or write at the same time).
  void write_text_atomically(const std::filesystem::path &file, const std::string &text);
} // namespace gradcontact::cases

#endif
