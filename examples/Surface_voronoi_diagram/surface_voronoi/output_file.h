// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writing an output file of the surface_voronoi program so that a failed write (a full disk,
// a file-size limit, a device that refuses data) never leaves a partial file behind and always
// reaches the caller as an error. Not part of the library.

#ifndef SVD_PROGRAM_OUTPUT_FILE_H
#define SVD_PROGRAM_OUTPUT_FILE_H

#include "errors.h"

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

namespace svd_program {

namespace internal {

inline std::string system_reason(int error)
{
  return error != 0 ? std::string(": ") + std::strerror(error) : std::string();
}

// Writes into `stream` (opened on `path`) with `write`, then flushes and closes it; returns
// the errno of the first failure seen, or -1 when the writer failed without one, or 0.
template <class Writer>
int write_and_close(std::ofstream& stream, const Writer& write)
{
  errno = 0;
  const bool written = write(stream);
  int error = errno;
  if(written && stream)
  {
    stream.flush();
    if(!stream) error = errno;
  }
  const bool ok = written && static_cast<bool>(stream);
  stream.close();
  if(!ok || stream.fail())
    return error != 0 ? error : (errno != 0 ? errno : -1);
  return 0;
}

} // namespace internal

/// Writes the file `path` with `write(std::ostream&) -> bool` (false when the writer failed).
///
/// - A regular file, or a path that does not exist yet, is written as a temporary file in the
///   same folder and renamed over `path` only once it is complete: on failure the temporary
///   file is removed and `path` is left as it was. A symbolic link is followed, so the file it
///   names is replaced and the link kept. The new file gets the permissions the old one had
///   (or those a plain `open` would give under the umask).
/// - Anything else (a device such as `/dev/null` or `/dev/full`, a pipe) is never replaced: it
///   is written directly, flushed and checked.
///
/// \throws Write_error with a one-line message naming `path` and the system's reason
template <class Writer>
void write_output_file(const std::string& path, bool binary, const Writer& write)
{
  const std::ios::openmode mode = binary ? (std::ios::out | std::ios::binary) : std::ios::out;
  struct stat status;
  const bool exists = ::stat(path.c_str(), &status) == 0;
  if(exists && S_ISDIR(status.st_mode))
    throw Write_error("cannot write '" + path + "': it is a directory");
  if(exists && !S_ISREG(status.st_mode))
  {
    std::ofstream stream(path, mode);
    if(!stream)
      throw Write_error("cannot open '" + path + "' for writing" + internal::system_reason(errno));
    const int error = internal::write_and_close(stream, write);
    if(error != 0)
      throw Write_error("failed to write '" + path + "'" + internal::system_reason(error > 0 ? error : 0));
    return;
  }

  // the file that will be replaced: the target of a symbolic link, not the link
  std::string target = path;
  if(exists)
  {
    char resolved[PATH_MAX];
    if(::realpath(path.c_str(), resolved) != nullptr) target = resolved;
  }
  const std::size_t slash = target.find_last_of('/');
  const std::string folder = slash == std::string::npos ? std::string(".") : target.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? target : target.substr(slash + 1);
  std::string temporary = folder + (slash == std::string::npos ? "/" : "") + "." + name + ".partial-XXXXXX";
  const int descriptor = ::mkstemp(&temporary[0]);
  if(descriptor < 0)
    throw Write_error("cannot open '" + path + "' for writing" + internal::system_reason(errno));
  ::close(descriptor);
  // mkstemp makes the file private (0600); give it the permissions the output should have
  mode_t permissions = 0;
  if(exists) permissions = status.st_mode & 07777;
  else
  {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    permissions = 0666 & ~mask;
  }
  ::chmod(temporary.c_str(), permissions);

  int error = 0;
  try
  {
    std::ofstream stream(temporary, mode | std::ios::trunc);
    error = stream ? internal::write_and_close(stream, write) : (errno != 0 ? errno : -1);
  }
  catch(...)
  {
    std::remove(temporary.c_str());   // whatever the writer threw, no partial file stays
    throw;
  }
  if(error == 0 && std::rename(temporary.c_str(), target.c_str()) != 0) error = errno != 0 ? errno : -1;
  if(error != 0)
  {
    std::remove(temporary.c_str());
    throw Write_error("failed to write '" + path + "'" + internal::system_reason(error > 0 ? error : 0));
  }
}

} // namespace svd_program

#endif // SVD_PROGRAM_OUTPUT_FILE_H
