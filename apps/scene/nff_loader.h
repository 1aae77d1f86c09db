#pragma once
// Reader for Eric Haines' Neutral File Format (NFF, the format of the Standard Procedural
// Databases): fills a SceneDescription following the reference reader's conventions
// (docs/architecture.md "Scene formats"; the full mapping and error list are in docs/nff.md).
#include <cstddef>
#include <string>

#include "apps/scene/scene_description.h"

namespace rayo {

// Facts about a load that are not errors but that a caller may want to report.
struct NffLoadInfo {
    size_t lines = 0;  // lines in the file
};

// Reads the whole file at once and parses it. Throws InputError: where = path and message
// "cannot open ..." when the file cannot be read, where = "path:line" for bad content.
SceneDescription load_nff_file(const std::string& path, NffLoadInfo* info = nullptr);

// Parses NFF text; `source_name` is used in error locations ("source_name:line") and as
// SceneDescription::source.
SceneDescription load_nff_string(const std::string& text, const std::string& source_name,
                                 NffLoadInfo* info = nullptr);

}  // namespace rayo
