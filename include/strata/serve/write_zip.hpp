#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "strata/core/result.hpp"

namespace strata::serve {

/// A file to put in an archive.
struct ZipEntry {
  std::string name;              ///< its name in the archive ("png/ring_0001.png"), '/' separated
  std::filesystem::path source;  ///< the file to read
};

/// Writes a ZIP archive (PKWARE APPNOTE 6.3, no ZIP64): each entry deflated, or stored when
/// deflate does not make it smaller; dates 1980-01-01 so that the same files give the same bytes.
/// Written under a temporary name and renamed when complete.
/// @return Error{BadInput} naming the file that cannot be read or written, or when an entry or
/// the archive would pass 4 GiB or 65535 entries
Result<void> write_zip(const std::filesystem::path& archive, const std::vector<ZipEntry>& entries);

/// The entries for every regular file under `folder`, named `prefix` + their relative path,
/// sorted by name.
Result<std::vector<ZipEntry>> zip_entries_of_folder(const std::filesystem::path& folder,
                                                    const std::string& prefix);

}  // namespace strata::serve
