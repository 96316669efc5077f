// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bounded parsers of the mesh formats the surface_voronoi program reads (OFF, OBJ, PLY,
// STL), from one buffer holding the whole file. They replace CGAL's stream readers in the
// program, because a file must never crash, hang or exhaust the program, and every error
// must name the line (text) or the element (binary):
//  - every count read from a file is checked against what the rest of the buffer can hold
//    (at the smallest size a record can have) before anything is allocated;
//  - every index is parsed as an integer (never through a floating-point value) and
//    range-checked; `3.5`, `1e11` or `-1` (where not allowed) are errors;
//  - coordinates are parsed with `std::from_chars` (correctly rounded, as the `strtod` and
//    `sscanf` that CGAL's readers use), so valid files give the same doubles bit for bit;
//  - an error is an svd_program::Input_error whose message starts with `line L: ` for text
//    and names the element (`face 5: `) for binary data; the caller prefixes the file.
//
// Grammar accepted, by format (anything else is an error, except where "skipped"):
//  - OFF: a keyword `OFF`, optionally with the prefixes `ST`, `C`, `N` in that order (`COFF`,
//    `NOFF`, `CNOFF`, `STOFF`, ...), then the counts `vertices faces [edges]` (on the keyword's
//    line or the next one); one vertex a line, whose first 3 numbers are x y z (the others,
//    colour, normal or texture numbers, are skipped); one face a line, `n i1 ... in` followed
//    by optional colour numbers (skipped); `#` starts a comment. A line with content after the
//    declared faces is an error. `4OFF` and `nOFF` are refused. Binary OFF (`OFF BINARY` or
//    `NOFF BINARY`, the data after the keyword's line; CGAL 5.5 could not read it): big-endian
//    int32 counts, float32 x y z [nx ny nz] a vertex, int32 n, n int32 indices, int32 k and k
//    float32 colour components a face; errors name the vertex or face. Binary OFF with vertex
//    colours or texture coordinates is refused.
//  - OBJ: `v x y z [w]` and `f a b c ...` records, each corner written `i`, `i/t`, `i//n` or
//    `i/t/n`, 1-based, negative = relative to the last vertex so far; other records skipped;
//    `#` starts a comment. The file must end with a line end after its last face (a face line
//    cut short is an error).
//  - PLY: `ascii`, `binary_little_endian`, `binary_big_endian` 1.0; any scalar type; an
//    element `vertex` with scalar properties x, y, z, an element `face` with a list property
//    `vertex_indices` or `vertex_index` of an integer type; other elements and properties
//    skipped; the header is checked line by line before the body is read.
//  - STL: binary when the size is exactly 84 + 50 n for the triangle count n of the header;
//    otherwise ASCII (`solid ... facet ... vertex x y z ... endfacet ... endsolid`), 3 vertices
//    a facet. Identical points are merged, numbered in order of first appearance.
//
// The largest polygon accepted has `max_polygon_corners` corners.

#ifndef SVD_PROGRAM_MESH_FILE_PARSERS_H
#define SVD_PROGRAM_MESH_FILE_PARSERS_H

#include "errors.h"
#include "input_file.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <vector>

namespace svd_program {

/// The largest polygon (number of corners) a mesh file may hold.
constexpr std::size_t max_polygon_corners = 10000000;

namespace mesh_parsers {

typedef std::vector<std::vector<std::size_t>> Polygons;

// ------------------------------------------------------------------------------ numbers

enum class Number_read { ok, not_a_number, non_finite, out_of_range };

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// A decimal floating-point number, the whole token: optional sign, digits, point, exponent.
// Overflow is non-finite; underflow gives the nearest double (as strtod), zero or subnormal.
template <class Real>
Number_read read_real(std::string_view token, Real& value)
{
  const char* b = token.data();
  const char* e = b + token.size();
  if(b != e && *b == '+')
  {
    ++b;
    if(b != e && (*b == '-' || *b == '+'))
      return Number_read::not_a_number;
  }
  if(b == e)
    return Number_read::not_a_number;
  const std::from_chars_result r = std::from_chars(b, e, value, std::chars_format::general);
  if(r.ec == std::errc::result_out_of_range)
  {
    // rare: let strtod say what the nearest value is (HUGE_VAL, or a subnormal, or 0)
    const std::string copy(b, e);
    char* end = nullptr;
    if(std::is_same<Real, float>::value)
      value = static_cast<Real>(std::strtof(copy.c_str(), &end));
    else
      value = static_cast<Real>(std::strtod(copy.c_str(), &end));
    if(end != copy.c_str() + copy.size())
      return Number_read::not_a_number;
  }
  else if(r.ec != std::errc() || r.ptr != e)
    return Number_read::not_a_number;
  if(!std::isfinite(value))
    return Number_read::non_finite;
  return Number_read::ok;
}

// A decimal integer, the whole token, optionally signed.
inline Number_read read_integer(std::string_view token, std::int64_t& value, bool allow_sign)
{
  const char* b = token.data();
  const char* e = b + token.size();
  if(b != e && *b == '+')
    ++b;
  else if(b != e && *b == '-' && !allow_sign)
    return Number_read::not_a_number;
  if(b == e || *b == '+' || (*b == '-' && b != token.data()))
    return Number_read::not_a_number;
  const std::from_chars_result r = std::from_chars(b, e, value, 10);
  if(r.ptr != e || (r.ec != std::errc() && r.ec != std::errc::result_out_of_range))
    return Number_read::not_a_number;
  if(r.ec == std::errc::result_out_of_range)
    return Number_read::out_of_range;
  return Number_read::ok;
}

// A count or index: a non-negative decimal integer.
inline Number_read read_unsigned(std::string_view token, std::uint64_t& value)
{
  const char* b = token.data();
  const char* e = b + token.size();
  if(b != e && *b == '+')
    ++b;
  if(b == e || *b < '0' || *b > '9')
    return Number_read::not_a_number;
  const std::from_chars_result r = std::from_chars(b, e, value, 10);
  if(r.ptr != e || (r.ec != std::errc() && r.ec != std::errc::result_out_of_range))
    return Number_read::not_a_number;
  if(r.ec == std::errc::result_out_of_range)
    return Number_read::out_of_range;
  return Number_read::ok;
}

inline std::string line_text(std::size_t line) { return "line " + std::to_string(line) + ": "; }

// ---------------------------------------------------------------------------- text cursor

// Walks a text buffer line by line; a record is a line with at least one token once the
// comment (from `comment` to the end of the line) is removed.
class Text_cursor
{
public:
  // `lines_before`: how many lines of the file come before `begin`
  Text_cursor(const char* begin, const char* end, char comment, std::size_t lines_before = 0)
    : next_(begin), end_(end), lines_seen_(lines_before), comment_(comment)
  {}

  // Moves to the next record; false at the end of the buffer.
  bool next_record()
  {
    while(next_ != end_)
    {
      const char* start = next_;
      const char* nl = static_cast<const char*>(std::memchr(start, '\n', std::size_t(end_ - start)));
      newline_ = (nl != nullptr);
      const char* stop = newline_ ? nl : end_;
      next_ = newline_ ? nl + 1 : end_;
      line_ = ++lines_seen_;
      if(comment_ != '\0')
      {
        const char* c = static_cast<const char*>(std::memchr(start, comment_, std::size_t(stop - start)));
        if(c != nullptr)
          stop = c;
      }
      while(start != stop && is_blank(*start))
        ++start;
      if(start != stop)
      {
        token_ = start;
        record_end_ = stop;
        return true;
      }
    }
    token_ = record_end_ = end_;
    return false;
  }

  // The next token of the current record; false when the record has no more.
  bool next_token(std::string_view& token)
  {
    const char* p = token_;
    while(p != record_end_ && is_blank(*p))
      ++p;
    if(p == record_end_)
    {
      token_ = p;
      return false;
    }
    const char* q = p;
    while(q != record_end_ && !is_blank(*q))
      ++q;
    token = std::string_view(p, std::size_t(q - p));
    token_ = q;
    return true;
  }

  // The next token, moving on to the following records when this one is used up.
  bool next_token_anywhere(std::string_view& token)
  {
    while(!next_token(token))
      if(!next_record())
        return false;
    return true;
  }

  // Tokens left in the current record, without consuming them.
  std::size_t tokens_left() const
  {
    std::size_t n = 0;
    const char* p = token_;
    while(p != record_end_)
    {
      while(p != record_end_ && is_blank(*p))
        ++p;
      if(p == record_end_)
        break;
      ++n;
      while(p != record_end_ && !is_blank(*p))
        ++p;
    }
    return n;
  }

  // The rest of the current record, unparsed.
  std::string_view rest_of_record() const { return std::string_view(token_, std::size_t(record_end_ - token_)); }
  void skip_rest_of_record() { token_ = record_end_; }

  // 1-based line of the current record
  std::size_t line() const { return line_; }
  // number of lines seen so far (the last line, at the end of the buffer)
  std::size_t lines_seen() const { return lines_seen_; }
  // whether the current record's line ends with a line end
  bool record_has_line_end() const { return newline_; }
  // bytes after the current line
  std::size_t bytes_left() const { return std::size_t(end_ - next_); }
  // where the line after the current record starts
  const char* next_line_start() const { return next_; }
  // whether anything other than blanks, line ends and comments remains after the current record
  bool only_blank_left()
  {
    Text_cursor copy = *this;
    return !copy.next_record();
  }

private:
  const char* next_;
  const char* end_;
  const char* token_ = nullptr;
  const char* record_end_ = nullptr;
  std::size_t line_ = 0;
  std::size_t lines_seen_;
  char comment_;
  bool newline_ = false;
};

// ----------------------------------------------------------------------------------- OFF

inline std::string vertices_text(std::size_t n) { return std::to_string(n) + (n == 1 ? " vertex" : " vertices"); }

template <class Point_3>
void parse_binary_off(const char* begin, const char* end, bool normals, std::vector<Point_3>& points,
                      Polygons& polygons);

template <class Point_3>
void parse_off(const char* data, std::size_t size, std::vector<Point_3>& points, Polygons& polygons)
{
  Text_cursor in(data, data + size, '#');
  if(!in.next_record())
    throw Input_error("the file is empty (expected the keyword OFF)");
  std::string_view keyword;
  in.next_token(keyword);
  {
    // [ST][C][N]OFF
    std::string_view k = keyword;
    if(k.substr(0, 2) == "ST") k.remove_prefix(2);
    if(!k.empty() && k[0] == 'C') k.remove_prefix(1);
    if(!k.empty() && k[0] == 'N') k.remove_prefix(1);
    if(k != "OFF")
    {
      const bool variant = keyword.size() >= 3 && keyword.substr(keyword.size() - 3) == "OFF";
      throw Input_error(line_text(in.line()) + (variant ? "the OFF variant " + quoted_token(keyword) +
                                                          " is not supported (only OFF, COFF, NOFF, CNOFF, STOFF and the like)"
                                                        : "expected the keyword OFF, found " + quoted_token(keyword)));
    }
  }
  std::string_view token;
  if(in.tokens_left() > 0)
  {
    std::string_view rest = in.rest_of_record();
    while(!rest.empty() && is_blank(rest.front())) rest.remove_prefix(1);
    if(rest.substr(0, 6) == "BINARY")
    {
      const std::string_view k = keyword.substr(0, keyword.size() - 3);
      if(k.find('C') != std::string_view::npos || k.find('T') != std::string_view::npos)
        throw Input_error(line_text(in.line()) + "binary " + printable_text(keyword) +
                          " is not supported (binary OFF with colours or texture coordinates; write it as text)");
      parse_binary_off(in.next_line_start(), data + size, k.find('N') != std::string_view::npos, points, polygons);
      return;
    }
  }
  else if(!in.next_record())
    throw Input_error(line_text(in.lines_seen()) + "the file ends before the counts (vertices faces edges)");
  const std::size_t counts_line = in.line();
  std::uint64_t counts[3] = { 0, 0, 0 };
  std::size_t number_of_counts = 0;
  while(in.next_token(token))
  {
    if(number_of_counts == 3)
      throw Input_error(line_text(counts_line) + "expected the counts 'vertices faces edges', found more numbers");
    const Number_read r = read_unsigned(token, counts[number_of_counts]);
    if(r == Number_read::out_of_range)
      throw Input_error(line_text(counts_line) + "count " + quoted_token(token) + " is out of range");
    if(r != Number_read::ok)
      throw Input_error(line_text(counts_line) + "expected the counts 'vertices faces edges', found " + quoted_token(token));
    ++number_of_counts;
  }
  if(number_of_counts < 2)
    throw Input_error(line_text(counts_line) + "expected the counts 'vertices faces edges', found " +
                      std::to_string(number_of_counts) + " number" + (number_of_counts == 1 ? "" : "s"));
  const std::uint64_t nv = counts[0], nf = counts[1];
  // The smallest vertex line is "0 0 0\n" (6 bytes), the smallest face line "3 0 1 2\n" (8);
  // the last line may lack its line end.
  const std::uint64_t room = std::uint64_t(in.bytes_left()) + 1;
  if(nv > room / 6 || nf > room / 8 || nv * 6 + nf * 8 > room)
    throw Input_error(line_text(counts_line) + "the header declares " + std::to_string(nv) + " vertices and " +
                      std::to_string(nf) + " faces, but the remaining " + std::to_string(in.bytes_left()) +
                      " bytes of the file cannot hold them");

  points.clear();
  polygons.clear();
  points.reserve(static_cast<std::size_t>(nv));
  polygons.reserve(static_cast<std::size_t>(nf));
  for(std::uint64_t i = 0; i < nv; ++i)
  {
    if(!in.next_record())
      throw Input_error(line_text(in.lines_seen()) + "the file ends after " + std::to_string(i) + " of the " +
                        vertices_text(nv) + " the header declares");
    double c[3];
    for(int k = 0; k < 3; ++k)
    {
      if(!in.next_token(token))
        throw Input_error(line_text(in.line()) + "vertex " + std::to_string(i) + " has " + std::to_string(k) +
                          " coordinate" + (k == 1 ? "" : "s") + ", expected 3 (x y z)");
      const Number_read r = read_real(token, c[k]);
      if(r == Number_read::non_finite)
        throw Input_error(line_text(in.line()) + "vertex " + std::to_string(i) + " has a non-finite coordinate " +
                          quoted_token(token));
      if(r != Number_read::ok)
        throw Input_error(line_text(in.line()) + "vertex " + std::to_string(i) + ": coordinate " + quoted_token(token) +
                          " is not a number");
    }
    in.skip_rest_of_record(); // colour, normal, texture coordinates
    points.emplace_back(c[0], c[1], c[2]);
  }
  for(std::uint64_t f = 0; f < nf; ++f)
  {
    if(!in.next_record())
      throw Input_error(line_text(in.lines_seen()) + "the file ends after " + std::to_string(f) + " of the " +
                        std::to_string(nf) + " faces the header declares");
    auto face = [f] { return "face " + std::to_string(f); };   // built only for a message
    in.next_token(token);
    std::uint64_t degree = 0;
    const Number_read r = read_unsigned(token, degree);
    if(r == Number_read::not_a_number)
      throw Input_error(line_text(in.line()) + face() + ": the number of vertices " + quoted_token(token) +
                        " is not a non-negative integer");
    const std::size_t available = in.tokens_left();
    if(r == Number_read::out_of_range || degree > available)
    {
      const std::string declared = r == Number_read::out_of_range ? printable_text(token, max_echoed_token_length)
                                                                  : std::to_string(degree);
      throw Input_error(line_text(in.line()) + face() + " declares " + declared + " vertices but " +
                        (in.only_blank_left() ? "the file ends after " : "its line holds only ") +
                        std::to_string(available));
    }
    if(degree < 3)
      throw Input_error(line_text(in.line()) + face() + " has " + std::to_string(degree) +
                        " vertices (a face needs at least 3)");
    if(degree > max_polygon_corners)
      throw Input_error(line_text(in.line()) + face() + " has " + std::to_string(degree) +
                        " vertices; the largest polygon accepted has " + std::to_string(max_polygon_corners));
    std::vector<std::size_t> polygon(static_cast<std::size_t>(degree));
    for(std::size_t& v : polygon)
    {
      in.next_token(token);
      std::uint64_t index = 0;
      const Number_read ri = read_unsigned(token, index);
      if(ri == Number_read::not_a_number)
        throw Input_error(line_text(in.line()) + face() + ": vertex index " + quoted_token(token) +
                          " is not a non-negative integer");
      if(ri == Number_read::out_of_range || index >= nv)
        throw Input_error(line_text(in.line()) + face() + ": vertex index " +
                          printable_text(token, max_echoed_token_length) + " is out of range (the file has " +
                          vertices_text(nv) + ")");
      v = static_cast<std::size_t>(index);
    }
    in.skip_rest_of_record(); // colour
    polygons.push_back(std::move(polygon));
  }
  if(in.next_record())
    throw Input_error(line_text(in.line()) + "unexpected content after the " + std::to_string(nf) +
                      " faces the header declares (does the file hold more faces than its header says?)");
}

// ----------------------------------------------------------------------------------- OBJ

template <class Point_3>
void parse_obj(const char* data, std::size_t size, std::vector<Point_3>& points, Polygons& polygons)
{
  Text_cursor in(data, data + size, '#');
  points.clear();
  polygons.clear();
  std::vector<std::size_t> face_line;
  std::string_view token;
  while(in.next_record())
  {
    in.next_token(token);
    if(token == "v")
    {
      double c[3];
      for(int k = 0; k < 3; ++k)
      {
        if(!in.next_token(token))
          throw Input_error(line_text(in.line()) + "vertex " + std::to_string(points.size()) + " has " +
                            std::to_string(k) + " coordinate" + (k == 1 ? "" : "s") + ", expected 3 (x y z)");
        const Number_read r = read_real(token, c[k]);
        if(r == Number_read::non_finite)
          throw Input_error(line_text(in.line()) + "vertex " + std::to_string(points.size()) +
                            " has a non-finite coordinate " + quoted_token(token));
        if(r != Number_read::ok)
          throw Input_error(line_text(in.line()) + "vertex " + std::to_string(points.size()) + ": coordinate " +
                            quoted_token(token) + " is not a number");
      }
      points.emplace_back(c[0], c[1], c[2]);
    }
    else if(token == "f")
    {
      const std::string face = "face " + std::to_string(polygons.size());
      if(!in.record_has_line_end())
        throw Input_error(line_text(in.line()) + face +
                          ": the file ends in the middle of the face's line (no line end after it: the file is cut short)");
      const std::size_t corners = in.tokens_left();
      if(corners < 3)
        throw Input_error(line_text(in.line()) + face + " has " + std::to_string(corners) +
                          " vertices (a face needs at least 3)");
      if(corners > max_polygon_corners)
        throw Input_error(line_text(in.line()) + face + " has " + std::to_string(corners) +
                          " vertices; the largest polygon accepted has " + std::to_string(max_polygon_corners));
      std::vector<std::size_t> polygon;
      polygon.reserve(corners);
      while(in.next_token(token))
      {
        // i, i/t, i//n or i/t/n
        const std::size_t slash = token.find('/');
        const std::string_view index_text = token.substr(0, slash);
        if(slash != std::string_view::npos)
        {
          const std::string_view rest = token.substr(slash + 1);
          const std::size_t slash2 = rest.find('/');
          const std::string_view t = rest.substr(0, slash2);
          const std::string_view n = slash2 == std::string_view::npos ? std::string_view() : rest.substr(slash2 + 1);
          std::int64_t ignored = 0;
          const bool ok_t = t.empty() ? slash2 != std::string_view::npos
                                      : read_integer(t, ignored, true) == Number_read::ok;
          const bool ok_n = slash2 == std::string_view::npos || read_integer(n, ignored, true) == Number_read::ok;
          if(!ok_t || !ok_n)
            throw Input_error(line_text(in.line()) + face + ": corner " + quoted_token(token) +
                              " is not of the form i, i/t, i//n or i/t/n");
        }
        std::int64_t index = 0;
        const Number_read r = read_integer(index_text, index, true);
        if(r == Number_read::not_a_number)
          throw Input_error(line_text(in.line()) + face + ": vertex index " + quoted_token(index_text) +
                            " is not an integer");
        const std::string range = " is out of range (" + vertices_text(points.size()) + " so far in the file)";
        if(r == Number_read::out_of_range)
          throw Input_error(line_text(in.line()) + face + ": vertex index " +
                            printable_text(index_text, max_echoed_token_length) + range);
        if(index == 0)
          throw Input_error(line_text(in.line()) + face + ": vertex index 0 is not valid (OBJ indices start at 1)");
        if(index < 0)
        {
          if(std::uint64_t(-(index + 1)) >= points.size())
            throw Input_error(line_text(in.line()) + face + ": relative vertex index " + std::to_string(index) + range);
          polygon.push_back(points.size() - static_cast<std::size_t>(-(index + 1)) - 1);
        }
        else
          polygon.push_back(static_cast<std::size_t>(index - 1)); // checked at the end
      }
      polygons.push_back(std::move(polygon));
      face_line.push_back(in.line());
    }
    // other records (vt, vn, o, g, s, usemtl, mtllib, l, p, ...) are skipped
  }
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t v : polygons[f])
      if(v >= points.size())
        throw Input_error(line_text(face_line[f]) + "face " + std::to_string(f) + ": vertex index " +
                          std::to_string(v + 1) + " is out of range (the file has " + vertices_text(points.size()) + ")");
}

// ----------------------------------------------------------------------------------- PLY

enum class Ply_type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

inline bool ply_type_from_name(std::string_view name, Ply_type& type)
{
  static const struct { const char* name; Ply_type type; } table[] = {
    { "char", Ply_type::int8 },     { "int8", Ply_type::int8 },     { "uchar", Ply_type::uint8 },
    { "uint8", Ply_type::uint8 },   { "short", Ply_type::int16 },   { "int16", Ply_type::int16 },
    { "ushort", Ply_type::uint16 }, { "uint16", Ply_type::uint16 }, { "int", Ply_type::int32 },
    { "int32", Ply_type::int32 },   { "uint", Ply_type::uint32 },   { "uint32", Ply_type::uint32 },
    { "float", Ply_type::float32 }, { "float32", Ply_type::float32 }, { "double", Ply_type::float64 },
    { "float64", Ply_type::float64 } };
  for(const auto& entry : table)
    if(name == entry.name)
    {
      type = entry.type;
      return true;
    }
  return false;
}

inline std::size_t ply_size(Ply_type t)
{
  switch(t)
  {
  case Ply_type::int8: case Ply_type::uint8: return 1;
  case Ply_type::int16: case Ply_type::uint16: return 2;
  case Ply_type::int32: case Ply_type::uint32: case Ply_type::float32: return 4;
  default: return 8;
  }
}

inline bool ply_is_integer(Ply_type t) { return t != Ply_type::float32 && t != Ply_type::float64; }

inline void ply_integer_range(Ply_type t, std::int64_t& lo, std::int64_t& hi)
{
  switch(t)
  {
  case Ply_type::int8: lo = -128; hi = 127; break;
  case Ply_type::uint8: lo = 0; hi = 255; break;
  case Ply_type::int16: lo = -32768; hi = 32767; break;
  case Ply_type::uint16: lo = 0; hi = 65535; break;
  case Ply_type::int32: lo = std::numeric_limits<std::int32_t>::min(); hi = std::numeric_limits<std::int32_t>::max(); break;
  default: lo = 0; hi = std::numeric_limits<std::uint32_t>::max(); break;
  }
}

struct Ply_property
{
  std::string name;
  Ply_type type = Ply_type::float32;      // the item type of a list
  Ply_type count_type = Ply_type::uint8;  // lists only
  bool is_list = false;
  std::size_t line = 0;
};

struct Ply_element
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<Ply_property> properties;
  std::size_t line = 0;
};

// A value read from a PLY body: integers exactly, reals as their double value.
struct Ply_value
{
  std::int64_t integer = 0;
  double real = 0;
};

class Ply_binary_source
{
public:
  Ply_binary_source(const unsigned char* begin, const unsigned char* end, bool big_endian)
    : p_(begin), end_(end), big_(big_endian)
  {}
  std::size_t bytes_left() const { return std::size_t(end_ - p_); }
  // false when the data ends
  bool read(Ply_type t, Ply_value& v)
  {
    const std::size_t n = ply_size(t);
    if(bytes_left() < n)
      return false;
    unsigned char b[8];
    if(big_)
      for(std::size_t i = 0; i < n; ++i) b[i] = p_[n - 1 - i];
    else
      std::memcpy(b, p_, n);
    p_ += n;
    switch(t)
    {
    case Ply_type::int8: { std::int8_t x; std::memcpy(&x, b, 1); v.integer = x; v.real = x; break; }
    case Ply_type::uint8: { std::uint8_t x; std::memcpy(&x, b, 1); v.integer = x; v.real = x; break; }
    case Ply_type::int16: { std::int16_t x; std::memcpy(&x, b, 2); v.integer = x; v.real = x; break; }
    case Ply_type::uint16: { std::uint16_t x; std::memcpy(&x, b, 2); v.integer = x; v.real = x; break; }
    case Ply_type::int32: { std::int32_t x; std::memcpy(&x, b, 4); v.integer = x; v.real = x; break; }
    case Ply_type::uint32: { std::uint32_t x; std::memcpy(&x, b, 4); v.integer = x; v.real = x; break; }
    case Ply_type::float32: { float x; std::memcpy(&x, b, 4); v.real = x; break; }
    case Ply_type::float64: { double x; std::memcpy(&x, b, 8); v.real = x; break; }
    }
    return true;
  }
  void skip(std::size_t n) { p_ += n; }

private:
  const unsigned char* p_;
  const unsigned char* end_;
  bool big_;
};

template <class Point_3>
void parse_ply(const char* data, std::size_t size, std::vector<Point_3>& points, Polygons& polygons)
{
  // --- header, line by line
  const char* p = data;
  const char* const end = data + size;
  std::size_t line = 0;
  auto next_line = [&](std::string_view& text) {
    if(p == end)
      return false;
    const char* nl = static_cast<const char*>(std::memchr(p, '\n', std::size_t(end - p)));
    const char* stop = nl ? nl : end;
    text = std::string_view(p, std::size_t(stop - p));
    if(!text.empty() && text.back() == '\r')
      text.remove_suffix(1);
    p = nl ? nl + 1 : end;
    ++line;
    return true;
  };
  auto words = [](std::string_view text) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while(i < text.size() && out.size() < 8)
    {
      while(i < text.size() && is_blank(text[i])) ++i;
      const std::size_t s = i;
      while(i < text.size() && !is_blank(text[i])) ++i;
      if(i > s) out.push_back(text.substr(s, i - s));
    }
    return out;
  };

  std::string_view text;
  if(!next_line(text) || text != "ply")
    throw Input_error("line 1: expected the PLY signature 'ply', found " + quoted_token(text));
  enum { none, ascii, little, big } format = none;
  std::vector<Ply_element> elements;
  bool ended = false;
  while(next_line(text))
  {
    const std::vector<std::string_view> w = words(text);
    if(w.empty())
      throw Input_error(line_text(line) + "empty line in the header");
    if(w[0] == "comment" || w[0] == "obj_info")
      continue;
    if(w[0] == "end_header")
    {
      ended = true;
      break;
    }
    if(w[0] == "format")
    {
      if(format != none)
        throw Input_error(line_text(line) + "a second 'format' line");
      if(w.size() != 3 || w[2] != "1.0")
        throw Input_error(line_text(line) + "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      if(w[1] == "ascii") format = ascii;
      else if(w[1] == "binary_little_endian") format = little;
      else if(w[1] == "binary_big_endian") format = big;
      else
        throw Input_error(line_text(line) + "unknown format " + quoted_token(w[1]));
    }
    else if(w[0] == "element")
    {
      if(w.size() != 3)
        throw Input_error(line_text(line) + "expected 'element NAME COUNT'");
      Ply_element e;
      e.name = std::string(w[1]);
      e.line = line;
      const Number_read r = read_unsigned(w[2], e.count);
      if(r != Number_read::ok)
        throw Input_error(line_text(line) + "element " + quoted_token(w[1]) + ": count " + quoted_token(w[2]) +
                          (r == Number_read::out_of_range ? " is out of range" : " is not a non-negative integer"));
      for(const Ply_element& other : elements)
        if(other.name == e.name)
          throw Input_error(line_text(line) + "a second element " + quoted_token(w[1]));
      elements.push_back(std::move(e));
    }
    else if(w[0] == "property")
    {
      if(elements.empty())
        throw Input_error(line_text(line) + "property before any element");
      Ply_property prop;
      prop.line = line;
      if(w.size() >= 2 && w[1] == "list")
      {
        if(w.size() != 5)
          throw Input_error(line_text(line) + "expected 'property list COUNT_TYPE ITEM_TYPE NAME'");
        if(!ply_type_from_name(w[2], prop.count_type))
          throw Input_error(line_text(line) + "unknown type " + quoted_token(w[2]));
        if(!ply_type_from_name(w[3], prop.type))
          throw Input_error(line_text(line) + "unknown type " + quoted_token(w[3]));
        if(!ply_is_integer(prop.count_type))
          throw Input_error(line_text(line) + "the count type of a list must be an integer type, not " + quoted_token(w[2]));
        prop.is_list = true;
        prop.name = std::string(w[4]);
      }
      else
      {
        if(w.size() != 3)
          throw Input_error(line_text(line) + "expected 'property TYPE NAME'");
        if(!ply_type_from_name(w[1], prop.type))
          throw Input_error(line_text(line) + "unknown type " + quoted_token(w[1]));
        prop.name = std::string(w[2]);
      }
      for(const Ply_property& other : elements.back().properties)
        if(other.name == prop.name)
          throw Input_error(line_text(line) + "a second property " + quoted_token(prop.name) + " in element " +
                            quoted_token(elements.back().name));
      elements.back().properties.push_back(std::move(prop));
    }
    else
      throw Input_error(line_text(line) + "unknown header keyword " + quoted_token(w[0]));
  }
  if(!ended)
    throw Input_error(line_text(line) + "the file ends before 'end_header'");
  if(format == none)
    throw Input_error(line_text(line) + "the header has no 'format' line");

  // --- what to take from the elements
  const Ply_element* vertex = nullptr;
  const Ply_element* face = nullptr;
  int xyz[3] = { -1, -1, -1 };
  int face_list = -1;
  for(const Ply_element& e : elements)
  {
    if(e.count > 0 && e.properties.empty())
      throw Input_error(line_text(e.line) + "element " + quoted_token(e.name) + " has records but no properties");
    if(e.name == "vertex")
    {
      vertex = &e;
      for(std::size_t k = 0; k < e.properties.size(); ++k)
        for(int c = 0; c < 3; ++c)
          if(e.properties[k].name == std::string(1, char('x' + c)))
          {
            if(e.properties[k].is_list)
              throw Input_error(line_text(e.properties[k].line) + "vertex property '" + e.properties[k].name +
                                "' is a list, expected a scalar");
            xyz[c] = int(k);
          }
      for(int c = 0; c < 3; ++c)
        if(xyz[c] < 0)
          throw Input_error(line_text(e.line) + "element 'vertex' has no property '" + std::string(1, char('x' + c)) + "'");
    }
    else if(e.name == "face")
    {
      face = &e;
      for(std::size_t k = 0; k < e.properties.size(); ++k)
        if(e.properties[k].name == "vertex_indices" || e.properties[k].name == "vertex_index")
        {
          if(!e.properties[k].is_list)
            throw Input_error(line_text(e.properties[k].line) + "face property '" + e.properties[k].name +
                              "' is not a list");
          if(!ply_is_integer(e.properties[k].type))
            throw Input_error(line_text(e.properties[k].line) + "face property '" + e.properties[k].name +
                              "' must hold integers");
          face_list = int(k);
        }
      if(face_list < 0)
        throw Input_error(line_text(e.line) + "element 'face' has no list property 'vertex_indices' (or 'vertex_index')");
    }
  }
  if(vertex == nullptr)
    throw Input_error("the header has no element 'vertex'");
  if(face == nullptr)
    throw Input_error("the header has no element 'face'");

  // --- body
  points.clear();
  polygons.clear();
  const std::uint64_t nv = vertex->count;
  std::vector<std::size_t> polygon_line; // ascii only
  auto out_of_room = [&](const Ply_element& e, std::uint64_t most) {
    return Input_error(line_text(e.line) + "element " + quoted_token(e.name) + " declares " + std::to_string(e.count) +
                       " records, but the rest of the file can hold at most " + std::to_string(most));
  };
  auto face_name = [](std::uint64_t r) { return "face " + std::to_string(r); };
  if(format == ascii)
  {
    Text_cursor in(p, end, '\0', line);
    std::string_view token;
    // the ascii body: every value is a token; records need not be one a line
    auto next_value = [&](const Ply_element& e, std::uint64_t record, const Ply_property& prop, Ply_type type,
                          Ply_value& v, const char* what) {
      if(!in.next_token_anywhere(token))
        throw Input_error(line_text(in.lines_seen()) + "the file ends inside " + e.name + " " + std::to_string(record) +
                          " (reading its " + what + " '" + prop.name + "')");
      if(ply_is_integer(type))
      {
        std::int64_t lo = 0, hi = 0;
        ply_integer_range(type, lo, hi);
        const Number_read r = read_integer(token, v.integer, true);
        if(r == Number_read::not_a_number)
          throw Input_error(line_text(in.line()) + e.name + " " + std::to_string(record) + ": " + what + " '" +
                            prop.name + "' " + quoted_token(token) + " is not an integer");
        if(r == Number_read::out_of_range || v.integer < lo || v.integer > hi)
          throw Input_error(line_text(in.line()) + e.name + " " + std::to_string(record) + ": " + what + " '" +
                            prop.name + "' " + quoted_token(token) + " is out of range for its type");
        v.real = double(v.integer);
        return;
      }
      Number_read r;
      if(type == Ply_type::float32)
      {
        float x = 0;
        r = read_real(token, x);
        v.real = x;
      }
      else
        r = read_real(token, v.real);
      if(r == Number_read::not_a_number)
        throw Input_error(line_text(in.line()) + e.name + " " + std::to_string(record) + ": " + what + " '" +
                          prop.name + "' " + quoted_token(token) + " is not a number");
      if(r == Number_read::non_finite)
        v.real = std::numeric_limits<double>::quiet_NaN(); // reported below if it is a coordinate
    };
    for(const Ply_element& e : elements)
    {
      const std::uint64_t room = (std::uint64_t(end - p) + 1) / (2 * e.properties.size() + (e.properties.empty() ? 1 : 0));
      if(e.count > room)
        throw out_of_room(e, room);
      if(&e == vertex)
        points.reserve(static_cast<std::size_t>(e.count));
      if(&e == face)
      {
        polygons.reserve(static_cast<std::size_t>(e.count));
        polygon_line.reserve(static_cast<std::size_t>(e.count));
      }
      for(std::uint64_t r = 0; r < e.count; ++r)
      {
        double c[3] = { 0, 0, 0 };
        std::string bad_coordinate;
        for(std::size_t k = 0; k < e.properties.size(); ++k)
        {
          const Ply_property& prop = e.properties[k];
          Ply_value v;
          if(!prop.is_list)
          {
            next_value(e, r, prop, prop.type, v, "property");
            if(&e == vertex)
              for(int j = 0; j < 3; ++j)
                if(int(k) == xyz[j])
                {
                  c[j] = v.real;
                  if(!std::isfinite(v.real) && bad_coordinate.empty())
                    bad_coordinate = quoted_token(token);
                }
            continue;
          }
          next_value(e, r, prop, prop.count_type, v, "list count");
          const std::size_t count_line = in.line();
          if(v.integer < 0)
            throw Input_error(line_text(in.line()) + e.name + " " + std::to_string(r) + ": list '" + prop.name +
                              "' has a negative count " + std::to_string(v.integer));
          const std::uint64_t count = std::uint64_t(v.integer);
          const bool is_face = (&e == face && int(k) == face_list);
          if(count > (std::uint64_t(in.bytes_left()) + std::uint64_t(in.rest_of_record().size()) + 1) / 2)
            throw Input_error(line_text(in.line()) + e.name + " " + std::to_string(r) + ": list '" + prop.name +
                              "' declares " + std::to_string(count) + " items but the rest of the file cannot hold them");
          if(is_face)
          {
            if(count < 3)
              throw Input_error(line_text(in.line()) + face_name(r) + " has " + std::to_string(count) +
                                " vertices (a face needs at least 3)");
            if(count > max_polygon_corners)
              throw Input_error(line_text(in.line()) + face_name(r) + " has " + std::to_string(count) +
                                " vertices; the largest polygon accepted has " + std::to_string(max_polygon_corners));
            std::vector<std::size_t> polygon(static_cast<std::size_t>(count));
            for(std::size_t& index : polygon)
            {
              next_value(e, r, prop, prop.type, v, "list");
              if(v.integer < 0)
                throw Input_error(line_text(in.line()) + face_name(r) + ": vertex index " +
                                  std::to_string(v.integer) + " is negative");
              index = static_cast<std::size_t>(v.integer);
            }
            polygons.push_back(std::move(polygon));
            polygon_line.push_back(count_line);
          }
          else
            for(std::uint64_t i = 0; i < count; ++i)
              next_value(e, r, prop, prop.type, v, "list");
        }
        if(&e == vertex)
        {
          if(!bad_coordinate.empty())
            throw Input_error(line_text(in.line()) + "vertex " + std::to_string(r) + " has a non-finite coordinate " +
                              bad_coordinate);
          points.emplace_back(c[0], c[1], c[2]);
        }
      }
    }
  }
  else
  {
    Ply_binary_source in(reinterpret_cast<const unsigned char*>(p), reinterpret_cast<const unsigned char*>(end),
                         format == big);
    for(const Ply_element& e : elements)
    {
      std::uint64_t smallest = 0;
      for(const Ply_property& prop : e.properties)
        smallest += prop.is_list ? ply_size(prop.count_type) : ply_size(prop.type);
      const std::uint64_t room = smallest == 0 ? 0 : std::uint64_t(in.bytes_left()) / smallest;
      if(e.count > room)
        throw out_of_room(e, room);
      if(&e == vertex)
        points.reserve(static_cast<std::size_t>(e.count));
      if(&e == face)
        polygons.reserve(static_cast<std::size_t>(e.count));
      for(std::uint64_t r = 0; r < e.count; ++r)
      {
        double c[3] = { 0, 0, 0 };
        for(std::size_t k = 0; k < e.properties.size(); ++k)
        {
          const Ply_property& prop = e.properties[k];
          Ply_value v;
          if(!prop.is_list)
          {
            if(!in.read(prop.type, v))
              throw Input_error(e.name + " " + std::to_string(r) + ": the file ends inside the record");
            if(&e == vertex)
              for(int j = 0; j < 3; ++j)
                if(int(k) == xyz[j])
                  c[j] = v.real;
            continue;
          }
          if(!in.read(prop.count_type, v))
            throw Input_error(e.name + " " + std::to_string(r) + ": the file ends inside the record");
          if(v.integer < 0)
            throw Input_error(e.name + " " + std::to_string(r) + ": list '" + prop.name + "' has a negative count " +
                              std::to_string(v.integer));
          const std::uint64_t count = std::uint64_t(v.integer);
          const std::uint64_t item = ply_size(prop.type);
          if(count > in.bytes_left() / item)
            throw Input_error(e.name + " " + std::to_string(r) + ": list '" + prop.name + "' declares " +
                              std::to_string(count) + " items (" + std::to_string(count * item) +
                              " bytes) but only " + std::to_string(in.bytes_left()) + " bytes remain");
          if(&e == face && int(k) == face_list)
          {
            if(count < 3)
              throw Input_error(face_name(r) + " has " + std::to_string(count) + " vertices (a face needs at least 3)");
            if(count > max_polygon_corners)
              throw Input_error(face_name(r) + " has " + std::to_string(count) +
                                " vertices; the largest polygon accepted has " + std::to_string(max_polygon_corners));
            std::vector<std::size_t> polygon(static_cast<std::size_t>(count));
            for(std::size_t& index : polygon)
            {
              in.read(prop.type, v);
              if(v.integer < 0)
                throw Input_error(face_name(r) + ": vertex index " + std::to_string(v.integer) + " is negative");
              index = static_cast<std::size_t>(v.integer);
            }
            polygons.push_back(std::move(polygon));
          }
          else
            in.skip(static_cast<std::size_t>(count * item));
        }
        if(&e == vertex)
          points.emplace_back(c[0], c[1], c[2]);
      }
    }
  }
  // indices: the vertex element may come after the faces, so check once both are read
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t v : polygons[f])
      if(v >= nv)
        throw Input_error((polygon_line.empty() ? std::string() : line_text(polygon_line[f])) + face_name(f) +
                          ": vertex index " + std::to_string(v) + " is out of range (the file has " +
                          vertices_text(static_cast<std::size_t>(nv)) + ")");
}

// ---------------------------------------------------------------------------- binary OFF

template <class Point_3>
void parse_binary_off(const char* begin, const char* end, bool normals, std::vector<Point_3>& points,
                      Polygons& polygons)
{
  Ply_binary_source in(reinterpret_cast<const unsigned char*>(begin), reinterpret_cast<const unsigned char*>(end), true);
  Ply_value v;
  std::int64_t counts[3];
  for(std::int64_t& c : counts)
  {
    if(!in.read(Ply_type::int32, v))
      throw Input_error("binary OFF: the file ends inside the counts");
    c = v.integer;
  }
  if(counts[0] < 0 || counts[1] < 0)
    throw Input_error("binary OFF: the header declares a negative count (" + std::to_string(counts[0]) + " vertices, " +
                      std::to_string(counts[1]) + " faces)");
  const std::uint64_t nv = std::uint64_t(counts[0]), nf = std::uint64_t(counts[1]);
  const std::uint64_t vertex_bytes = 12 + (normals ? 12 : 0), face_bytes = 20;
  if(nv * vertex_bytes + nf * face_bytes > in.bytes_left())
    throw Input_error("binary OFF: the header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                      " faces, but the remaining " + std::to_string(in.bytes_left()) + " bytes cannot hold them");
  points.clear();
  polygons.clear();
  points.reserve(static_cast<std::size_t>(nv));
  polygons.reserve(static_cast<std::size_t>(nf));
  auto skip_colour = [&](const std::string& element) {
    if(!in.read(Ply_type::int32, v))
      throw Input_error(element + ": the file ends inside the record");
    if(v.integer < 0 || v.integer > 4)
      throw Input_error(element + ": " + std::to_string(v.integer) + " colour components (at most 4)");
    if(std::uint64_t(v.integer) * 4 > in.bytes_left())
      throw Input_error(element + ": the file ends inside the record");
    in.skip(std::size_t(v.integer) * 4);
  };
  for(std::uint64_t i = 0; i < nv; ++i)
  {
    const std::string element = "vertex " + std::to_string(i);
    double c[3];
    for(double& x : c)
    {
      if(!in.read(Ply_type::float32, v))
        throw Input_error(element + ": the file ends inside the record");
      x = v.real;
    }
    if(normals)
    {
      if(in.bytes_left() < 12)
        throw Input_error(element + ": the file ends inside the record");
      in.skip(12);
    }
    points.emplace_back(c[0], c[1], c[2]);
  }
  for(std::uint64_t f = 0; f < nf; ++f)
  {
    const std::string element = "face " + std::to_string(f);
    if(!in.read(Ply_type::int32, v))
      throw Input_error(element + ": the file ends inside the record");
    if(v.integer < 3)
      throw Input_error(element + " has " + std::to_string(v.integer) + " vertices (a face needs at least 3)");
    const std::uint64_t degree = std::uint64_t(v.integer);
    if(degree * 4 > in.bytes_left())
      throw Input_error(element + " declares " + std::to_string(degree) + " vertices but only " +
                        std::to_string(in.bytes_left()) + " bytes remain");
    if(degree > max_polygon_corners)
      throw Input_error(element + " has " + std::to_string(degree) + " vertices; the largest polygon accepted has " +
                        std::to_string(max_polygon_corners));
    std::vector<std::size_t> polygon(static_cast<std::size_t>(degree));
    for(std::size_t& index : polygon)
    {
      in.read(Ply_type::int32, v);
      if(v.integer < 0 || std::uint64_t(v.integer) >= nv)
        throw Input_error(element + ": vertex index " + std::to_string(v.integer) + " is out of range (the file has " +
                          vertices_text(static_cast<std::size_t>(nv)) + ")");
      index = static_cast<std::size_t>(v.integer);
    }
    skip_colour(element);
    polygons.push_back(std::move(polygon));
  }
  if(in.bytes_left() != 0)
    throw Input_error("binary OFF: " + std::to_string(in.bytes_left()) + " bytes after the " + std::to_string(nf) +
                      " faces the header declares");
}

// ----------------------------------------------------------------------------------- STL

// Numbers identical points in order of first appearance (-0 and +0 are the same point).
template <class Point_3>
class Point_merger
{
public:
  Point_merger(std::vector<Point_3>& points, std::size_t expected) : points_(points)
  {
    index_.reserve(expected);
  }
  std::size_t operator()(double x, double y, double z)
  {
    Key key;
    const double c[3] = { x + 0.0, y + 0.0, z + 0.0 };
    std::memcpy(key.bits.data(), c, sizeof(c));
    const auto inserted = index_.emplace(key, points_.size());
    if(inserted.second)
      points_.emplace_back(x, y, z);
    return inserted.first->second;
  }

private:
  struct Key
  {
    std::array<std::uint64_t, 3> bits;
    bool operator==(const Key& o) const { return bits == o.bits; }
  };
  struct Hash
  {
    std::size_t operator()(const Key& k) const
    {
      std::uint64_t h = 0x9E3779B97F4A7C15ull;
      for(std::uint64_t b : k.bits)
      {
        h ^= b + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
        h *= 0xff51afd7ed558ccdull;
      }
      return std::size_t(h ^ (h >> 33));
    }
  };
  std::vector<Point_3>& points_;
  std::unordered_map<Key, std::size_t, Hash> index_;
};

template <class Point_3>
void parse_stl(const char* data, std::size_t size, std::vector<Point_3>& points, Polygons& polygons)
{
  points.clear();
  polygons.clear();
  std::size_t start = 0;
  while(start < size && (is_blank(data[start]) || data[start] == '\n'))
    ++start;
  const bool says_solid = size - start >= 5 && std::memcmp(data + start, "solid", 5) == 0 &&
                          (size - start == 5 || is_blank(data[start + 5]) || data[start + 5] == '\n');
  if(size >= 84)
  {
    std::uint32_t n = 0;
    const unsigned char* b = reinterpret_cast<const unsigned char*>(data) + 80;
    n = std::uint32_t(b[0]) | (std::uint32_t(b[1]) << 8) | (std::uint32_t(b[2]) << 16) | (std::uint32_t(b[3]) << 24);
    const std::uint64_t expected = 84 + 50 * std::uint64_t(n);
    if(expected == size)
    {
      polygons.reserve(n);
      Point_merger<Point_3> merge(points, std::size_t(n) / 2 + 3);
      const char* t = data + 84;
      for(std::uint32_t f = 0; f < n; ++f, t += 50)
      {
        std::vector<std::size_t> triangle(3);
        for(int k = 0; k < 3; ++k)
        {
          float c[3];
          for(int j = 0; j < 3; ++j)
          {
            unsigned char le[4];
            std::memcpy(le, t + 12 + 12 * k + 4 * j, 4);
            const std::uint32_t bits = std::uint32_t(le[0]) | (std::uint32_t(le[1]) << 8) |
                                       (std::uint32_t(le[2]) << 16) | (std::uint32_t(le[3]) << 24);
            std::memcpy(&c[j], &bits, 4);
            if(!std::isfinite(c[j]))
              throw Input_error("triangle " + std::to_string(f) + " has a non-finite coordinate (" +
                                (std::isnan(c[j]) ? "nan" : c[j] > 0 ? "inf" : "-inf") + ")");
          }
          triangle[std::size_t(k)] = merge(c[0], c[1], c[2]);
        }
        polygons.push_back(std::move(triangle));
      }
      return;
    }
    if(!says_solid)
      throw Input_error("neither ASCII STL (it does not start with 'solid') nor binary STL (its header declares " +
                        std::to_string(n) + " triangles, which take " + std::to_string(expected) +
                        " bytes, but the file has " + std::to_string(size) + ")");
  }
  else if(!says_solid)
    throw Input_error("neither ASCII STL (it does not start with 'solid') nor binary STL (shorter than 84 bytes)");

  Text_cursor in(data, data + size, '\0');
  Point_merger<Point_3> merge(points, size / 200 + 3);
  std::string_view token;
  bool in_solid = false, any_solid = false;
  while(in.next_token_anywhere(token))
  {
    if(token == "solid")
    {
      if(in_solid)
        throw Input_error(line_text(in.line()) + "'solid' inside a solid (missing 'endsolid')");
      in_solid = any_solid = true;
      in.skip_rest_of_record(); // the name
    }
    else if(token == "endsolid")
    {
      if(!in_solid)
        throw Input_error(line_text(in.line()) + "'endsolid' without 'solid'");
      in_solid = false;
      in.skip_rest_of_record();
    }
    else if(token == "facet" && in_solid)
    {
      const std::size_t f = polygons.size();
      const std::string facet = "facet " + std::to_string(f);
      std::vector<std::size_t> triangle;
      triangle.reserve(3);
      for(;;)
      {
        if(!in.next_token_anywhere(token))
          throw Input_error(line_text(in.lines_seen()) + "the file ends inside " + facet + " (missing 'endfacet')");
        if(token == "endfacet")
          break;
        if(token == "facet" || token == "endsolid" || token == "solid")
          throw Input_error(line_text(in.line()) + facet + ": " + quoted_token(token) + " before 'endfacet'");
        if(token != "vertex")
          continue; // normal, outer loop, endloop and their numbers
        if(triangle.size() == 3)
          throw Input_error(line_text(in.line()) + facet + " has more than 3 vertices (STL holds triangles only)");
        double c[3];
        for(int k = 0; k < 3; ++k)
        {
          if(!in.next_token_anywhere(token))
            throw Input_error(line_text(in.lines_seen()) + "the file ends inside " + facet);
          const Number_read r = read_real(token, c[k]);
          if(r == Number_read::non_finite)
            throw Input_error(line_text(in.line()) + facet + " has a non-finite coordinate " + quoted_token(token));
          if(r != Number_read::ok)
            throw Input_error(line_text(in.line()) + facet + ": coordinate " + quoted_token(token) + " is not a number");
        }
        triangle.push_back(merge(c[0], c[1], c[2]));
      }
      if(triangle.size() != 3)
        throw Input_error(line_text(in.line()) + facet + " has " + std::to_string(triangle.size()) +
                          " vertices (STL holds triangles)");
      polygons.push_back(std::move(triangle));
    }
    else
      throw Input_error(line_text(in.line()) + "expected " + (in_solid ? "'facet' or 'endsolid'" : "'solid'") +
                        ", found " + quoted_token(token));
  }
  if(!any_solid)
    throw Input_error("the file holds no solid");
  if(in_solid)
    throw Input_error(line_text(in.lines_seen()) + "the file ends without 'endsolid' (is it cut short?)");
}

// ------------------------------------------------------------------------------- dispatch

/// Parses a whole mesh file held in memory into a polygon soup.
/// \param format `off`, `obj`, `ply` or `stl`
/// \throws svd_program::Input_error naming the line or element, without the file's name
template <class Point_3>
void parse_mesh(const char* data, std::size_t size, const std::string& format, std::vector<Point_3>& points,
                Polygons& polygons)
{
  if(format == "off")
    parse_off(data, size, points, polygons);
  else if(format == "obj")
    parse_obj(data, size, points, polygons);
  else if(format == "ply")
    parse_ply(data, size, points, polygons);
  else if(format == "stl")
    parse_stl(data, size, points, polygons);
  else
    throw Input_error("unknown format " + quoted_token(format) + " (expected off, obj, ply or stl)");
}

} // namespace mesh_parsers
} // namespace svd_program

#endif // SVD_PROGRAM_MESH_FILE_PARSERS_H
