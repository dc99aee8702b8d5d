#include "report/table.h"

#include "report/report.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;

  std::string format(const double x, const Number n)
  {
    if (n.style != 'g' && n.style != 'e' && n.style != 'f')
      throw std::invalid_argument(std::string("format: Number style '") + n.style + "'; valid: 'g', 'e' or 'f'");
    const char spec[] = {'%', '.', '*', n.style, '\0'};
    char b[64];
    // a fixed-point number may be longer than the buffer: its length is asked of snprintf first
    const int length = std::snprintf(b, sizeof b, spec, n.digits, x);
    if (length < 0 || static_cast<std::size_t>(length) < sizeof b)
      return b;
    std::string long_text(static_cast<std::size_t>(length) + 1, '\0');
    std::snprintf(long_text.data(), long_text.size(), spec, n.digits, x);
    long_text.pop_back();
    return long_text;
  }

  std::string md_escape(const std::string &text)
  {
    std::string out;
    for (const char c : text)
      out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
  }

  // --- Column ------------------------------------------------------------------------------------------------
  Column Column::both(std::string csv, std::string md)
  {
    Column c;
    c.csv_head = std::move(csv);
    c.md_head  = std::move(md);
    return c;
  }

  Column Column::csv_only(std::string csv) { return both(std::move(csv), ""); }

  Column Column::md_only(std::string md) { return both("", std::move(md)); }

  Column Column::csv_as(const Number n) const
  {
    Column c     = *this;
    c.csv_number = n;
    return c;
  }

  Column Column::md_as(const Number n) const
  {
    Column c    = *this;
    c.md_number = n;
    return c;
  }

  Column Column::quoted() const
  {
    Column c = *this;
    c.quote  = true;
    return c;
  }

  Column Column::missing_as(std::string md) const
  {
    Column c  = *this;
    c.missing = std::move(md);
    return c;
  }

  // --- Cell --------------------------------------------------------------------------------------------------
  Cell::Cell(const double x)
    : kind(Kind::number)
    , number(x)
  {}

  Cell::Cell(std::string t)
    : kind(Kind::text)
    , text(std::move(t))
  {}

  Cell::Cell(const char *t)
    : Cell(std::string(t))
  {}

  Cell Cell::md_text(std::string t) const
  {
    Cell c     = *this;
    c.markdown = std::move(t);
    return c;
  }

  std::string Cell::csv(const Column &column, const Number table_number) const
  {
    switch (kind)
      {
        case Kind::number:
          return format(number, column.csv_number.value_or(table_number));
        case Kind::integer:
          return std::to_string(integer);
        case Kind::text:
          return column.quote ? csv_quote(text) : text;
        default:
          return "";
      }
  }

  std::string Cell::md(const Column &column) const
  {
    if (markdown)
      return md_escape(*markdown);
    switch (kind)
      {
        case Kind::number:
          return format(number, column.md_number);
        case Kind::integer:
          return std::to_string(integer);
        case Kind::text:
          return md_escape(text);
        default:
          return column.missing;
      }
  }

  // --- Table -------------------------------------------------------------------------------------------------
  Table::Table(std::vector<Column> c, const Number n)
    : columns(std::move(c))
    , csv_number(n)
  {}

  void Table::add(std::vector<Cell> row)
  {
    if (row.size() != columns.size())
      throw std::invalid_argument("Table::add: a row of " + std::to_string(row.size()) + " cells in a table of " +
                                  std::to_string(columns.size()) + " columns");
    rows.push_back(std::move(row));
  }

  void Table::append(const Table &other)
  {
    if (other.columns.size() != columns.size())
      throw std::invalid_argument("Table::append: a table of " + std::to_string(other.columns.size()) +
                                  " columns onto one of " + std::to_string(columns.size()));
    rows.insert(rows.end(), other.rows.begin(), other.rows.end());
  }

  std::string Table::csv() const
  {
    std::string out;
    const auto line = [&](const auto &field) {
      bool first = true;
      for (std::size_t j = 0; j < columns.size(); ++j)
        if (columns[j].in_csv())
          {
            out += (first ? "" : ",") + field(j);
            first = false;
          }
      out += '\n';
    };
    line([&](const std::size_t j) { return columns[j].csv_head; });
    for (const std::vector<Cell> &row : rows)
      line([&](const std::size_t j) { return row[j].csv(columns[j], csv_number); });
    return out;
  }

  std::string Table::md() const
  {
    std::string out;
    const auto line = [&](const auto &field) {
      out += '|';
      for (std::size_t j = 0; j < columns.size(); ++j)
        if (columns[j].in_md())
          out += ' ' + field(j) + " |";
      out += '\n';
    };
    line([&](const std::size_t j) { return columns[j].md_head; });
    out += '|';
    for (const Column &c : columns)
      if (c.in_md())
        out += "---|";
    out += '\n';
    for (const std::vector<Cell> &row : rows)
      line([&](const std::size_t j) { return row[j].md(columns[j]); });
    return out;
  }

  void Table::write_csv(const fs::path &file) const { write_text(file, csv()); }

  // --- files -------------------------------------------------------------------------------------------------
  void write_table_files(const fs::path &folder, const std::string &stem, const Table &table, const std::string &md)
  {
    write_table_csv(folder, stem, table);
    write_text_atomically(folder / (stem + ".md"), md);
  }

  void write_table_csv(const fs::path &folder, const std::string &stem, const Table &table)
  {
    write_text_atomically(folder / (stem + ".csv"), table.csv());
  }

  void write_document(const fs::path &folder, const std::string &stem, const std::string &md)
  {
    write_text_atomically(folder / (stem + ".md"), md);
  }

  void write_text(const fs::path &file, const std::string &text)
  {
    std::ofstream out(file);
    out << text;
    out.close();
    if (!out)
      throw std::runtime_error("cannot write " + file.string());
  }

  void write_text_atomically(const fs::path &file, const std::string &text)
  {
    const fs::path tmp = temporary_sibling(file);
    try
      {
        write_text(tmp, text);
      }
    catch (...)
      {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        throw;
      }
    fs::rename(tmp, file);
  }
} // namespace gradcontact::cases
