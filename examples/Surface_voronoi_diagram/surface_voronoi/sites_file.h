// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The surface_voronoi program's plain-text record files: the sites file (`x y z [weight]` per line) and the
// breaklines file (two vertex indices per line) share one grammar, so that
// users learn one set of rules and errors look the same:
//  - one record a line; fields separated by spaces or tabs;
//  - `#` starts a comment running to the end of the line;
//  - blank, whitespace-only and comment-only lines are skipped;
//  - a CR before the LF (Windows line ends) is accepted;
//  - errors cite the physical line number, 1-based.
// Record (site) indices are the count of data lines before the record, 0-based.

#ifndef SVD_PROGRAM_SITES_FILE_H
#define SVD_PROGRAM_SITES_FILE_H

#include "errors.h"
#include "input_file.h"

#include <CGAL/number_utils.h>

#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <istream>
#include <limits>
#include <locale>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace svd_program {

/// One site as read from a sites file.
struct Site_record
{
  double x = 0, y = 0, z = 0;
  /// the fourth field, or 0 when the line has only three
  double weight = 0;
  /// whether the line had a fourth field
  bool has_weight = false;
  /// physical line number in the file (1-based), for later error messages
  std::size_t line = 0;
};

/// One line of a breaklines file: two vertex indices.
struct Index_pair_record
{
  std::size_t first = 0, second = 0;
  /// physical line number in the file (1-based), for later error messages
  std::size_t line = 0;
};

namespace internal {

// Tokens go into messages escaped (control bytes and bytes outside ASCII as \xNN) and
// shortened, so that a message stays one readable line of printable ASCII.
inline std::string printable_token(const std::string& token)
{
  return printable_text(token, max_echoed_token_length);
}

inline std::string line_prefix(const std::string& file_kind, std::size_t line)
{
  return file_kind + " line " + std::to_string(line) + ": ";
}

enum class Number_status { ok, not_a_number, non_finite };

// Decimal numbers only: what strtod accepts beyond that (hexadecimal floats,
// leading white space other than our separators) is not part of the grammar.
// strtod follows the C locale's LC_NUMERIC, which is "C" (decimal point '.')
// unless the program calls setlocale(); surface_voronoi never does.
inline Number_status parse_double(const std::string& token, double& value)
{
  if(token.empty())
    return Number_status::not_a_number;
  const char* begin = token.c_str();
  char* end = nullptr;
  value = std::strtod(begin, &end);
  if(end == begin || static_cast<std::size_t>(end - begin) != token.size())
    return Number_status::not_a_number;
  // "nan", "inf", "infinity" and overflowing literals (strtod gives HUGE_VAL)
  // all land here; underflow to a subnormal or zero is accepted as the
  // nearest double.
  if(!std::isfinite(value))
    return Number_status::non_finite;
  for(char c : token)
    if(!((c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E'))
      return Number_status::not_a_number;
  return Number_status::ok;
}

inline bool parse_index(const std::string& token, std::size_t& value, bool& overflow)
{
  overflow = false;
  if(token.empty())
    return false;
  for(char c : token)
    if(c < '0' || c > '9')
      return false;
  errno = 0;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(token.c_str(), &end, 10);
  if(errno == ERANGE || v > static_cast<unsigned long long>(std::numeric_limits<std::size_t>::max()))
  {
    overflow = true;
    return false;
  }
  value = static_cast<std::size_t>(v);
  return true;
}

// The 17 significant digits of "%.17g" identify every double uniquely, so the
// text reads back to the same bits; the classic locale keeps the '.' whatever
// locale the caller's stream carries.
inline std::string format_double(double v)
{
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << std::setprecision(17) << v;
  return out.str();
}

} // namespace internal

/// The longest line the record files (sites, breaklines) may have, in bytes.
constexpr std::size_t max_record_line_length = 65536;

/// The most records (sites, or breaklines pairs) a record file may hold.
constexpr std::size_t max_records_in_file = 10000000;

/// Splits a stream into records following the grammar shared by the program's
/// text files: one record a line, fields separated by spaces or tabs, `#` to
/// the end of the line is a comment, lines without fields are skipped, a
/// trailing CR is dropped. Calls `record(line, fields)` for each record as it is read,
/// so that memory holds one line at a time (at most `max_record_line_length` bytes).
///
/// \param in the stream to read to its end
/// \param file_kind how messages name the file, e.g. `sites file`
/// \param record called with the physical line number (1-based) and the fields
///        (`std::vector<std::string>`) of every line with at least one field
/// \pre nothing
/// \throws svd_program::Input_error if a line is longer than `max_record_line_length`,
///         or the stream fails other than by reaching its end
template <class Record_callback>
void for_each_record(std::istream& in, const std::string& file_kind, Record_callback&& record)
{
  std::string text;
  std::vector<std::string> fields;
  std::size_t line = 0;
  std::streambuf* buffer = in.rdbuf();
  bool more = (buffer != nullptr);
  while(more)
  {
    text.clear();
    bool got_any = false;
    for(;;)
    {
      const std::char_traits<char>::int_type c = buffer->sbumpc();
      if(std::char_traits<char>::eq_int_type(c, std::char_traits<char>::eof()))
      {
        more = false;
        break;
      }
      got_any = true;
      if(c == '\n')
        break;
      if(text.size() >= max_record_line_length)
        throw Input_error(internal::line_prefix(file_kind, line + 1) + "the line is longer than " +
                          std::to_string(max_record_line_length) + " bytes");
      text.push_back(std::char_traits<char>::to_char_type(c));
    }
    if(!got_any)
      break;
    ++line;
    if(!text.empty() && text.back() == '\r')
      text.pop_back();
    const std::size_t hash = text.find('#');
    if(hash != std::string::npos)
      text.erase(hash);
    fields.clear();
    std::size_t i = 0;
    while(i < text.size())
    {
      while(i < text.size() && (text[i] == ' ' || text[i] == '\t'))
        ++i;
      const std::size_t start = i;
      while(i < text.size() && text[i] != ' ' && text[i] != '\t')
        ++i;
      if(i > start)
        fields.push_back(text.substr(start, i - start));
    }
    if(!fields.empty())
      record(line, static_cast<const std::vector<std::string>&>(fields));
  }
  in.setstate(std::ios::eofbit);
  if(in.bad())
    throw Input_error(file_kind + ": read error after line " + std::to_string(line));
}

/// Splits a stream into records, as `for_each_record()`, and returns them all.
///
/// \param in the stream to read to its end
/// \pre nothing
/// \returns for every line with at least one field, its physical line number
///          (1-based) and its fields, in file order
/// \throws svd_program::Input_error as `for_each_record()`
inline std::vector<std::pair<std::size_t, std::vector<std::string>>> tokenize_records(std::istream& in)
{
  std::vector<std::pair<std::size_t, std::vector<std::string>>> records;
  for_each_record(in, "file", [&](std::size_t line, const std::vector<std::string>& fields) {
    records.emplace_back(line, fields);
  });
  return records;
}

/// Reads a sites file from a stream (e.g. an `std::istringstream` over bytes in memory, which
/// is how the sites reader's fuzzing harness calls it): any bytes give either the sites or
/// an svd_program::Input_error, with memory bounded by one line (`max_record_line_length`)
/// plus the sites read (at most `max_records_in_file`).
///
/// Each data line holds 3 or 4 decimal numbers, `x y z [weight]`,
/// with the grammar of `tokenize_records()`. Numbers are parsed with `std::strtod`,
/// which must consume the whole field, so the program's LC_NUMERIC locale must use
/// '.' as decimal point (true unless the program changes it with `setlocale()`).
/// Hexadecimal numbers are rejected.
///
/// \param in the stream to read to its end
/// \pre the C locale's LC_NUMERIC uses '.' as decimal point (the default)
/// \returns the sites in file order; the site index is the position in this vector
/// \throws svd_program::Input_error naming the physical line (1-based), e.g.
///         `sites file line 7: expected 3 or 4 numbers (x y z [weight]), found 2`,
///         `sites file line 3: 'abc' is not a number`,
///         `sites file line 9: non-finite value 'nan'` (also for `inf` and overflow like `1e999`)
inline std::vector<Site_record> read_sites_file(std::istream& in)
{
  const std::string kind = "sites file";
  std::vector<Site_record> sites;
  for_each_record(in, kind, [&](std::size_t line, const std::vector<std::string>& fields) {
    if(sites.size() == max_records_in_file)
      throw Input_error(internal::line_prefix(kind, line) + "more than " + std::to_string(max_records_in_file) +
                        " sites (the most a sites file may hold)");
    if(fields.size() != 3 && fields.size() != 4)
      throw Input_error(internal::line_prefix(kind, line) +
                        "expected 3 or 4 numbers (x y z [weight]), found " +
                        std::to_string(fields.size()));
    double values[4] = { 0, 0, 0, 0 };
    for(std::size_t k = 0; k < fields.size(); ++k)
    {
      switch(internal::parse_double(fields[k], values[k]))
      {
      case internal::Number_status::ok:
        break;
      case internal::Number_status::not_a_number:
        throw Input_error(internal::line_prefix(kind, line) + "'" +
                          internal::printable_token(fields[k]) + "' is not a number");
      case internal::Number_status::non_finite:
        throw Input_error(internal::line_prefix(kind, line) + "non-finite value '" +
                          internal::printable_token(fields[k]) + "'");
      }
    }
    Site_record site;
    site.x = values[0];
    site.y = values[1];
    site.z = values[2];
    site.has_weight = (fields.size() == 4);
    site.weight = values[3];
    site.line = line;
    sites.push_back(site);
  });
  return sites;
}

/// Reads a sites file from disk; see `read_sites_file(std::istream&)`.
/// \param filename the file to read
/// \pre as `read_sites_file(std::istream&)`
/// \throws svd_program::Input_error if the file cannot be opened, saying why
///         (`sites file 'FILE': cannot open the file: no such file`, `... permission denied`,
///         `sites file 'FILE': is a directory, not a file`), or breaks the grammar
inline std::vector<Site_record> read_sites_file(const std::string& filename)
{
  const std::string what = "sites file '" + printable_text(filename) + "'";
  check_input_path(filename, what);
  // Binary mode: line ends are handled by the grammar, identically on every platform.
  std::ifstream in(filename, std::ios::binary);
  if(!in)
    throw Input_error(what + ": cannot open the file: " + internal::open_failure_reason(errno ? errno : EACCES));
  return read_sites_file(in);
}

/// Writes sites in the format read by `read_sites_file()`: one line per site,
/// `x y z`, or `x y z w` on every line when some weight is non-zero. Numbers
/// have 17 significant digits, so reading the file back gives the same doubles.
///
/// \tparam PointRange a range of points with `x()`, `y()`, `z()` accepted by `CGAL::to_double()`
/// \param out the stream to write to
/// \param points the sites
/// \param weights empty, or one weight per site
/// \pre `weights.empty() || weights.size() == points.size()`
/// \throws svd_program::Input_error if the sizes differ, a value is not
///         finite (it could not be read back), or the stream fails
template <class PointRange>
void write_sites_file(std::ostream& out, const PointRange& points,
                      const std::vector<double>& weights = std::vector<double>())
{
  std::size_t n = 0;
  for(auto it = points.begin(); it != points.end(); ++it)
    ++n;
  if(!weights.empty() && weights.size() != n)
    throw Input_error("write_sites_file: " + std::to_string(weights.size()) + " weights for " +
                      std::to_string(n) + " sites");
  bool with_weights = false;
  for(double w : weights)
    if(w != 0)
      with_weights = true;

  std::size_t i = 0;
  for(const auto& p : points)
  {
    const double values[4] = { CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                               CGAL::to_double(p.z()), with_weights ? weights[i] : 0.0 };
    const std::size_t count = with_weights ? 4 : 3;
    std::string line;
    for(std::size_t k = 0; k < count; ++k)
    {
      if(!std::isfinite(values[k]))
        throw Input_error("write_sites_file: site " + std::to_string(i) +
                          " has a non-finite value");
      if(k > 0)
        line += ' ';
      line += internal::format_double(values[k]);
    }
    line += '\n';
    out << line;
    ++i;
  }
  if(!out)
    throw Input_error("write_sites_file: the output stream failed");
}

/// Reads records of two non-negative decimal integers (e.g. the vertex indices
/// of a breaklines file), with the grammar of `tokenize_records()`. Signs are
/// not accepted. Like `read_sites_file(std::istream&)`, it takes any bytes (the breaklines
/// reader's fuzzing entry point), in memory bounded by one line plus the records read.
///
/// \param in the stream to read to its end
/// \param file_kind how messages name the file, e.g. `breaklines file`
/// \pre nothing
/// \returns the pairs in file order, with their physical line numbers
/// \throws svd_program::Input_error naming the physical line (1-based), e.g.
///         `breaklines file line 4: expected 2 non-negative integers, found 3`,
///         `breaklines file line 4: '-3' is not a non-negative integer`,
///         `breaklines file line 4: '99999999999999999999999' is out of range`
inline std::vector<Index_pair_record> parse_index_pairs(std::istream& in,
                                                        const std::string& file_kind = "breaklines file")
{
  std::vector<Index_pair_record> pairs;
  for_each_record(in, file_kind, [&](std::size_t line, const std::vector<std::string>& fields) {
    if(pairs.size() == max_records_in_file)
      throw Input_error(internal::line_prefix(file_kind, line) + "more than " + std::to_string(max_records_in_file) +
                        " records (the most a file may hold)");
    if(fields.size() != 2)
      throw Input_error(internal::line_prefix(file_kind, line) +
                        "expected 2 non-negative integers, found " + std::to_string(fields.size()));
    std::size_t values[2] = { 0, 0 };
    for(std::size_t k = 0; k < 2; ++k)
    {
      bool overflow = false;
      if(!internal::parse_index(fields[k], values[k], overflow))
        throw Input_error(internal::line_prefix(file_kind, line) + "'" +
                          internal::printable_token(fields[k]) + "'" +
                          (overflow ? " is out of range" : " is not a non-negative integer"));
    }
    Index_pair_record pair;
    pair.first = values[0];
    pair.second = values[1];
    pair.line = line;
    pairs.push_back(pair);
  });
  return pairs;
}

/// Reads a breaklines file from disk; see `parse_index_pairs()`.
/// \param filename the file to read
/// \pre nothing
/// \throws svd_program::Input_error if the file cannot be opened, saying why
///         (`breaklines file 'FILE': cannot open the file: no such file`, `... is a directory,
///         not a file`), or breaks the grammar
inline std::vector<Index_pair_record> read_breaklines_file(const std::string& filename)
{
  const std::string what = "breaklines file '" + printable_text(filename) + "'";
  check_input_path(filename, what);
  std::ifstream in(filename, std::ios::binary);
  if(!in)
    throw Input_error(what + ": cannot open the file: " + internal::open_failure_reason(errno ? errno : EACCES));
  return parse_index_pairs(in);
}

} // namespace svd_program

#endif // SVD_PROGRAM_SITES_FILE_H
