// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the surface_voronoi program's readers share: opening an input file with a message
// that says exactly what is wrong (missing, a directory, unreadable, too large), reading a
// whole file into one buffer, and making text from a file safe to print in a one-line
// message (every byte outside printable ASCII is written \xNN, echoed tokens are capped).

#ifndef SVD_PROGRAM_INPUT_FILE_H
#define SVD_PROGRAM_INPUT_FILE_H

#include "errors.h"

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

namespace svd_program {

/// The largest mesh file the program reads (2 GiB): the file is read into memory in one
/// piece, and every count in it is bounded by what this many bytes can hold.
constexpr std::uint64_t max_mesh_file_bytes = std::uint64_t(2) << 30;

/// How many bytes of a token a message echoes at most (longer tokens end with `...`).
constexpr std::size_t max_echoed_token_length = 40;

/// Text made safe for a one-line message: a byte outside printable ASCII (a control
/// character, DEL, or any byte of a UTF-8 sequence) is written `\xNN`.
/// At most `max_length` bytes of `text` are kept; `...` marks a cut.
inline std::string printable_text(std::string_view text,
                                  std::size_t max_length = std::string_view::npos)
{
  std::string out;
  out.reserve(text.size() < 64 ? text.size() + 8 : 72);
  std::size_t i = 0;
  for(; i < text.size() && i < max_length; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if(c < 0x20 || c >= 0x7f)
    {
      char buffer[8];
      std::snprintf(buffer, sizeof(buffer), "\\x%02X", static_cast<unsigned>(c));
      out += buffer;
    }
    else
      out += static_cast<char>(c);
  }
  if(i < text.size())
    out += "...";
  return out;
}

/// A token from a file, quoted for a message: `'abc'`, escaped and capped as by
/// `printable_text()` to `max_echoed_token_length` bytes.
inline std::string quoted_token(std::string_view token)
{
  return "'" + printable_text(token, max_echoed_token_length) + "'";
}

namespace internal {

inline std::string open_failure_reason(int error)
{
  switch(error)
  {
  case ENOENT: return "no such file";
  case EACCES: return "permission denied";
  case EISDIR: return "it is a directory";
  case ENOTDIR: return "a component of the path is not a directory";
  case ELOOP: return "too many symbolic links";
  case ENAMETOOLONG: return "the name is too long";
  default: return printable_text(std::strerror(error));
  }
}

} // namespace internal

/// Checks that `filename` names something the program can read as a file, and explains
/// what is wrong otherwise.
///
/// \param filename the path, as given by the user
/// \param what how the message names the file, e.g. `sites file 'a.txt'`
/// \throws svd_program::Input_error `WHAT: cannot open the file: no such file` (or
///         `permission denied`, ...), or `WHAT: is a directory, not a file`
inline void check_input_path(const std::string& filename, const std::string& what)
{
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(filename, ec);
  if(ec || status.type() == std::filesystem::file_type::not_found)
  {
    const int error = (status.type() == std::filesystem::file_type::not_found) ? ENOENT : ec.value();
    throw Input_error(what + ": cannot open the file: " + internal::open_failure_reason(error));
  }
  if(status.type() == std::filesystem::file_type::directory)
    throw Input_error(what + ": is a directory, not a file");
}

/// Opens a file for reading (binary mode), or throws a message saying why it cannot be.
///
/// \param filename the path
/// \param what how the message names the file, as for `check_input_path()`
/// \returns an open `FILE*`; the caller closes it
/// \throws svd_program::Input_error as `check_input_path()`
inline std::FILE* open_input_file(const std::string& filename, const std::string& what)
{
  check_input_path(filename, what);
  errno = 0;
  std::FILE* file = std::fopen(filename.c_str(), "rb");
  if(file == nullptr)
    throw Input_error(what + ": cannot open the file: " + internal::open_failure_reason(errno ? errno : EACCES));
  return file;
}

/// Reads a whole file into `contents`, in one allocation for a regular file (whose size is
/// checked before anything is read), by chunks for anything else (a pipe, a device).
///
/// \param filename the path
/// \param what how messages name the file, as for `check_input_path()`
/// \param max_bytes the largest accepted size
/// \param contents the bytes of the file
/// \throws svd_program::Input_error as `check_input_path()`, when the file is larger than
///         `max_bytes`, or when reading fails
inline void read_whole_file(const std::string& filename, const std::string& what,
                            std::uint64_t max_bytes, std::string& contents)
{
  std::FILE* file = open_input_file(filename, what);
  struct Closer
  {
    std::FILE* f;
    ~Closer() { std::fclose(f); }
  } closer{ file };

  auto too_large = [&](std::uint64_t size) {
    return Input_error(what + ": the file is too large (" + (size == 0 ? std::string("more than ") : std::string()) +
                       std::to_string(size == 0 ? max_bytes : size) + " bytes; the largest file read is " +
                       std::to_string(max_bytes) + " bytes)");
  };
  contents.clear();
  std::error_code ec;
  const bool regular = std::filesystem::is_regular_file(filename, ec);
  if(regular && !ec)
  {
    const std::uintmax_t size = std::filesystem::file_size(filename, ec);
    if(!ec)
    {
      if(size > max_bytes)
        throw too_large(size);
      contents.resize(static_cast<std::size_t>(size));
      const std::size_t got = size == 0 ? 0 : std::fread(&contents[0], 1, contents.size(), file);
      if(got != contents.size())
      {
        if(std::ferror(file))
          throw Input_error(what + ": read error after " + std::to_string(got) + " bytes");
        contents.resize(got); // the file shrank meanwhile: take what is there
      }
      return;
    }
  }
  char buffer[1 << 16];
  for(;;)
  {
    const std::size_t got = std::fread(buffer, 1, sizeof(buffer), file);
    if(got > 0)
    {
      if(contents.size() + got > max_bytes)
        throw too_large(0);
      if(contents.capacity() < contents.size() + got)
      {
        // grow geometrically, but never past the limit (an endless device stops there)
        const std::uint64_t wanted = std::max<std::uint64_t>(2 * std::uint64_t(contents.capacity()), contents.size() + got);
        contents.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(wanted, max_bytes)));
      }
      contents.append(buffer, got);
    }
    if(got < sizeof(buffer))
    {
      if(std::ferror(file))
        throw Input_error(what + ": read error after " + std::to_string(contents.size()) + " bytes");
      return;
    }
  }
}

} // namespace svd_program

#endif // SVD_PROGRAM_INPUT_FILE_H
