#pragma once
// The temporary file an image is written to before it is renamed onto its final name, so that
// the final name holds a whole image or nothing (docs/limits.md, "Output"). Used by the
// in-memory writer and by the streaming one.
#include <cstddef>
#include <string>

namespace rayo {

// The longest file name the directory's file system takes (NAME_MAX, 255 on Linux).
size_t max_name_length(const std::string& dir);

// ".NAME.tmpPID.EXT" beside `path` (the extension last, so that OpenImageIO picks the format),
// the name shortened so that the temporary fits where the final name fits.
std::string temporary_path_for(const std::string& path);

// OpenImageIO's message with the temporary name replaced by the final one (the name the user
// gave), and the system's reason (errno `error`, 0 for none) appended when the message lacks it.
std::string write_failure(std::string message, int error, const std::string& tmp,
                          const std::string& path);

}  // namespace rayo
