#include "core/image/image_writers.h"

#include "core/image/exr_writer.h"
#include "core/image/output_encoding.h"
#include "core/image/png_writer.h"

namespace rayo {

bool writer_needs_image_library(const std::string& path, ImageWriterChoice choice) {
    const ImageFormat format = image_format_of(path);
    return choice == ImageWriterChoice::OpenImageIO ||
           (format != ImageFormat::Png && format != ImageFormat::Exr);
}

std::unique_ptr<ImageWriter> create_image_writer(const std::string& file, const ImageFileSpec& spec,
                                                 ImageWriterChoice choice, std::string& error) {
    if (writer_needs_image_library(file, choice))
        return image_library().create_writer(file, spec, error);
    return image_format_of(file) == ImageFormat::Png ? create_png_writer(file, spec, error)
                                                     : create_exr_writer(file, spec, error);
}

}  // namespace rayo
