// image_compare: how far an image is from a reference, measured after dividing both by the
// reference's mean, so that the numbers read as fractions of the reference's average brightness.
// Used by scripts/conformance.sh to compare rayo's renders of the SPD scenes with POV-Ray's.
//
// usage: image_compare IMAGE REFERENCE [--threshold T] [--max-off PERCENT]
//   prints: pixels_off_percent mean_relative_error psnr_db
//   exit 0, or 1 when more than PERCENT % of the pixels are off, 2 on bad input.
//
// Both images are read as float RGB (other channels are ignored) and must have the same size.
// With m the mean of the reference's RGB values, both are divided by m. A pixel is "off" when
// one of its channels differs by more than T (default 0.05: 5 % of the mean). The mean relative
// error is the mean absolute difference over all RGB values; PSNR = 20·log10(1 / RMS difference)
// (peak = the reference's mean), the form ImageBufAlgo::compare and idiff use. compare() itself
// is not used: with OIIO 2.4.7 it returned error = true for two valid images that merely differ,
// so a real error could not be told from a failed pixel.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

bool read_rgb(const std::string& path, OIIO::ImageBuf& rgb) {
    OIIO::ImageBuf image(path);
    if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT)) {
        std::fprintf(stderr, "image_compare: %s: %s\n", path.c_str(), image.geterror().c_str());
        return false;
    }
    if (image.nchannels() < 3) {
        std::fprintf(stderr, "image_compare: %s: expected at least 3 channels (RGB), got %d\n",
                     path.c_str(), image.nchannels());
        return false;
    }
    rgb = OIIO::ImageBufAlgo::channels(image, 3, {});  // the first three: R, G, B
    return !rgb.has_error();
}

// The number after a flag, or exit 2 naming the flag.
double number_after(int& i, int argc, char** argv) {
    const std::string flag = argv[i];
    char* end = nullptr;
    const double value = i + 1 < argc ? std::strtod(argv[i + 1], &end) : NAN;
    if (i + 1 >= argc || *end != '\0' || !std::isfinite(value) || value < 0) {
        std::fprintf(stderr, "image_compare: %s: expected a number >= 0\n", flag.c_str());
        std::exit(2);
    }
    ++i;
    return value;
}

}  // namespace

int main(int argc, char** argv) {
    std::string paths[2];
    int path_count = 0;
    double threshold = 0.05, max_off_percent = 100.0;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--threshold") {
            threshold = number_after(i, argc, argv);
        } else if (a == "--max-off") {
            max_off_percent = number_after(i, argc, argv);
        } else if (path_count < 2 && !a.empty() && a[0] != '-') {
            paths[path_count++] = a;
        } else {
            std::fprintf(stderr,
                         "usage: image_compare IMAGE REFERENCE [--threshold T] [--max-off %%]\n");
            return 2;
        }
    }
    if (path_count != 2) {
        std::fprintf(stderr,
                     "usage: image_compare IMAGE REFERENCE [--threshold T] [--max-off %%]\n");
        return 2;
    }
    OIIO::ImageBuf image, reference;
    if (!read_rgb(paths[0], image) || !read_rgb(paths[1], reference)) return 2;
    const OIIO::ROI a = image.roi(), b = reference.roi();
    if (a.width() != b.width() || a.height() != b.height()) {
        std::fprintf(stderr, "image_compare: sizes differ: %s is %dx%d, %s is %dx%d\n",
                     paths[0].c_str(), a.width(), a.height(), paths[1].c_str(), b.width(),
                     b.height());
        return 2;
    }
    std::vector<float> x(size_t(a.width()) * a.height() * 3), y(x.size());
    if (!image.get_pixels(image.roi(), OIIO::TypeDesc::FLOAT, x.data()) ||
        !reference.get_pixels(reference.roi(), OIIO::TypeDesc::FLOAT, y.data())) {
        std::fprintf(stderr, "image_compare: cannot read the pixels\n");
        return 2;
    }
    double mean = 0.0;
    for (const float v : y) mean += v;
    mean /= double(y.size());
    if (!(mean > 0.0) || !std::isfinite(mean)) {
        std::fprintf(stderr, "image_compare: %s: mean %g, cannot normalise by it\n",
                     paths[1].c_str(), mean);
        return 2;
    }
    size_t off = 0;
    double sum_abs = 0.0, sum_squares = 0.0;
    for (size_t p = 0; p < x.size(); p += 3) {
        double worst = 0.0;
        for (size_t c = p; c < p + 3; ++c) {
            const double d = std::abs(double(x[c]) - double(y[c])) / mean;
            worst = std::max(worst, std::isnan(d) ? INFINITY : d);
            sum_abs += d;
            sum_squares += d * d;
        }
        off += worst > threshold;
    }
    const double mean_error = sum_abs / double(x.size());
    const double psnr = 20.0 * std::log10(1.0 / std::sqrt(sum_squares / double(x.size())));
    const double off_percent = 100.0 * double(off) / (double(a.width()) * a.height());
    std::printf("%.2f %.4f %.2f\n", off_percent, mean_error, psnr);
    return off_percent > max_off_percent ? 1 : 0;
}
