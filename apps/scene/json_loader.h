#pragma once
// rayo's native scene format: versioned JSON ("rayo": 1), comments allowed, field names equal to
// the code's member names. Every field, default and error is described in docs/scene-format.md.
#include <string>

#include "apps/scene/input_file.h"
#include "apps/scene/scene_description.h"

namespace rayo {

// Reads and parses a scene file; mesh paths are resolved relative to the file's directory.
// Throws InputError: where = "<path>:<line>:<column>" for JSON syntax errors, otherwise
// "<path>#<JSON pointer>" of the offending value (or of the missing field).
// `access` says which files the scene may reference (apps/scene/input_file.h).
SceneDescription load_json_file(const std::string& path, const FileAccess& access = {});

// Parses scene text; `source_name` is used in error places and as SceneDescription::source,
// `base_dir` resolves relative mesh paths (core/path_util.h join_path: "" or "." mean the current
// directory).
SceneDescription load_json_string(const std::string& text, const std::string& source_name,
                                  const std::string& base_dir, const FileAccess& access = {});

}  // namespace rayo
