#pragma once
// Reader for Eric Haines' Neutral File Format (NFF, the format of the Standard Procedural
// Databases): fills a SceneDescription following the reference reader's conventions
// (docs/architecture.md "Scene formats"; the full mapping and error list are in docs/nff.md).
#include <cstddef>
#include <optional>
#include <string>

#include "apps/scene/scene_description.h"

namespace rayo {

// Facts about a load that are not errors but that a caller may want to report.
struct NffLoadInfo {
    size_t lines = 0;  // lines in the file
};

// Choices a caller (the CLI) may make about how a file is read.
struct NffOptions {
    // The intensity of each light whose `l` line gives no colour. Unset: 1/sqrt(N) for the N
    // lights of the file, the SPD's rule (the generators write NFF lights at 1 and scale every
    // other format by 1/sqrt(N), "for raytracers that don't scale the light intensity"; an NFF
    // reader applies the factor itself). 1 gives unit lights. Lights with a colour use it as
    // given, at intensity 1.
    std::optional<float> light_intensity;
};

// Reads the whole file at once and parses it. Throws InputError: where = path and message
// "cannot open ..." when the file cannot be read, where = "path:line" for bad content.
SceneDescription load_nff_file(const std::string& path, NffLoadInfo* info = nullptr,
                               const NffOptions& options = {});

// Parses NFF text; `source_name` is used in error locations ("source_name:line") and as
// SceneDescription::source.
SceneDescription load_nff_string(const std::string& text, const std::string& source_name,
                                 NffLoadInfo* info = nullptr, const NffOptions& options = {});

}  // namespace rayo
