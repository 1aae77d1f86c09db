// Tests of core/image_output: EXR round trips, the OCIO views of the shipped config against the
// sRGB formula (IEC 61966-2-1), seed 000's range modes, atomic writes and the $OCIO override.
#include "core/image/image_output.h"

#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"

namespace fs = std::filesystem;
namespace OCIO = OCIO_NAMESPACE;

namespace rayo {
namespace {

// A fresh directory under the system temp dir, removed (with its contents) at the end.
class TempDir {
  public:
    TempDir() {
        std::string pattern = (fs::temp_directory_path() / "rayo_image_output_XXXXXX").string();
        std::vector<char> buf(pattern.begin(), pattern.end());
        buf.push_back('\0');
        if (::mkdtemp(buf.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
        m_path = buf.data();
    }
    ~TempDir() {
        std::error_code ec;
        fs::permissions(m_path, fs::perms::owner_all, fs::perm_options::add, ec);
        fs::remove_all(m_path, ec);
    }
    const fs::path& path() const { return m_path; }
    std::string file(const std::string& name) const { return (m_path / name).string(); }

  private:
    fs::path m_path;
};

// Sets or unsets $OCIO for one scope and restores the previous state afterwards.
class ScopedOcioEnv {
  public:
    explicit ScopedOcioEnv(const std::optional<std::string>& value) {
        if (const char* old = std::getenv("OCIO")) m_old = old;
        if (value)
            ::setenv("OCIO", value->c_str(), 1);
        else
            ::unsetenv("OCIO");
    }
    ~ScopedOcioEnv() {
        if (m_old)
            ::setenv("OCIO", m_old->c_str(), 1);
        else
            ::unsetenv("OCIO");
    }

  private:
    std::optional<std::string> m_old;
};

std::set<std::string> listing(const fs::path& dir) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename());
    return names;
}

// IEC 61966-2-1 sRGB encoding of a linear value in [0,1].
double srgb_encode(double v) {
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

struct Loaded {
    OIIO::ImageSpec spec;
    std::vector<float> pixels;  // normalised to [0,1] for integer formats (OIIO's convention)
    std::vector<uint8_t> bytes;
    std::vector<uint16_t> words;
};

Loaded load(const std::string& path, OIIO::TypeDesc type) {
    // Read the stored (unassociated) values, without OpenImageIO premultiplying them.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path, &config);
    if (!in) throw std::runtime_error("cannot open " + path + ": " + OIIO::geterror());
    Loaded out;
    out.spec = in->spec();
    const size_t n = static_cast<size_t>(out.spec.width) * out.spec.height * out.spec.nchannels;
    void* data = nullptr;
    if (type == OIIO::TypeDesc::UINT8) {
        out.bytes.resize(n);
        data = out.bytes.data();
    } else if (type == OIIO::TypeDesc::UINT16) {
        out.words.resize(n);
        data = out.words.data();
    } else {
        out.pixels.resize(n);
        data = out.pixels.data();
    }
    if (!in->read_image(0, 0, 0, out.spec.nchannels, type, data))
        throw std::runtime_error("cannot read " + path + ": " + in->geterror());
    return out;
}

// One row of grey pixels with the given linear values (alpha 1).
Film grey_row(const std::vector<float>& values) {
    Film film(static_cast<int>(values.size()), 1);
    for (size_t i = 0; i < values.size(); ++i)
        film.set(static_cast<int>(i), 0, Vec3(values[i], values[i], values[i]));
    return film;
}

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(ImageOutputExr, FloatRoundTripIsBitExactWithMetadata) {
    TempDir dir;
    Film film(7, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 7; ++x)
            film.set(x, y, Vec3(0.1f * x + 1e-7f * y, 123456.78f * y - 3.25f, 1.0f / (x + 1.0f)),
                     0.25f * y);
    OutputOptions options;
    options.metadata["rayo:scene"] = "scenes/balls.nff";
    options.metadata["rayo:spp"] = "16";
    const std::string path = dir.file("film.exr");
    write_image(film, path, options);

    const Loaded back = load(path, OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(back.spec.width, 7);
    EXPECT_EQ(back.spec.height, 3);
    ASSERT_EQ(back.spec.nchannels, 4);
    EXPECT_EQ(back.spec.format, OIIO::TypeDesc::FLOAT);
    ASSERT_EQ(back.pixels.size(), film.rgba().size());
    EXPECT_EQ(
        0, std::memcmp(back.pixels.data(), film.rgba().data(), back.pixels.size() * sizeof(float)));
    EXPECT_EQ(back.spec.get_string_attribute("Software"), std::string("rayo ") + RAYO_VERSION);
    EXPECT_EQ(back.spec.get_string_attribute("rayo:scene"), "scenes/balls.nff");
    EXPECT_EQ(back.spec.get_string_attribute("rayo:spp"), "16");
    EXPECT_EQ(listing(dir.path()), std::set<std::string>{"film.exr"});
}

TEST(ImageOutputExr, HalfFloatStoresHalfValues) {
    TempDir dir;
    const std::vector<float> values = {0.0f, 0.18f, 0.5f, 1.0f, 3.14159f, 1000.0f};
    Film film = grey_row(values);
    OutputOptions options;
    options.half_float_exr = true;
    const std::string path = dir.file("half.exr");
    write_image(film, path, options);

    const Loaded back = load(path, OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(back.spec.format, OIIO::TypeDesc::HALF);
    ASSERT_EQ(back.pixels.size(), values.size() * 4);
    for (size_t i = 0; i < values.size(); ++i) {
        // A half has 11 significant bits: within 2^-11 relative of the float.
        EXPECT_NEAR(back.pixels[i * 4], values[i], values[i] / 2048.0f) << "value " << values[i];
        EXPECT_EQ(back.pixels[i * 4 + 3], 1.0f);
    }
    // Values that a half represents exactly come back exactly; 0.18 and pi do not.
    EXPECT_EQ(back.pixels[0 * 4], 0.0f);
    EXPECT_EQ(back.pixels[2 * 4], 0.5f);
    EXPECT_EQ(back.pixels[3 * 4], 1.0f);
    EXPECT_EQ(back.pixels[5 * 4], 1000.0f);
    EXPECT_NE(back.pixels[1 * 4], 0.18f);
    EXPECT_NE(back.pixels[4 * 4], 3.14159f);
}

TEST(ImageOutputPng, SrgbViewMatchesSrgbFormula) {
    ScopedOcioEnv env(std::nullopt);
    TempDir dir;
    const std::vector<float> values = {0.0f, 0.18f, 1.0f, 0.5f, 0.002f, 4.0f};
    Film film = grey_row(values);
    // The film is premultiplied: colour 0.5 at alpha 0.5 is stored as 0.25. The file holds the
    // unassociated colour through the view, and the alpha untransformed.
    film.set(3, 0, Vec3(0.25f, 0.25f, 0.25f), 0.5f);
    OutputOptions options;
    options.display = "sRGB";
    options.view = "sRGB";
    const std::string path = dir.file("grey.png");
    write_image(film, path, options);

    const Loaded back = load(path, OIIO::TypeDesc::UINT8);
    ASSERT_EQ(back.spec.nchannels, 4);
    ASSERT_EQ(back.bytes.size(), values.size() * 4);
    EXPECT_EQ(back.bytes[0], 0);
    EXPECT_NEAR(back.bytes[4], 118, 1);  // 0.18 -> 0.4614 -> 117.6
    EXPECT_EQ(back.bytes[8], 255);
    for (size_t i = 0; i < values.size(); ++i) {
        const double expected = std::round(255.0 * std::min(1.0, srgb_encode(values[i])));
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(back.bytes[i * 4 + c], expected, 1) << "linear " << values[i];
    }
    EXPECT_EQ(back.bytes[3 * 4 + 3], 128);  // alpha 0.5 -> 127.5 rounds to 128
    EXPECT_EQ(back.bytes[0 * 4 + 3], 255);
    EXPECT_EQ(back.bytes[5 * 4 + 0], 255);  // 4.0 clamped after the view
}

TEST(ImageOutputPng, DefaultDisplayAndViewAreSrgb) {
    ScopedOcioEnv env(std::nullopt);
    TempDir dir;
    const std::string path = dir.file("default.png");
    write_image(grey_row({0.18f}), path, OutputOptions{});
    const Loaded back = load(path, OIIO::TypeDesc::UINT8);
    EXPECT_NEAR(back.bytes[0], 118, 1);
}

TEST(ImageOutputPng, NormalizeMapsEachChannelMaximumTo255) {
    ScopedOcioEnv env(std::nullopt);
    TempDir dir;
    Film film(3, 1);
    film.set(0, 0, Vec3(4.0f, 1.0f, 0.0f));
    film.set(1, 0, Vec3(2.0f, 2.0f, 0.0f));
    film.set(2, 0, Vec3(1.0f, 0.5f, 0.0f));
    OutputOptions options;
    options.range = RangeMode::Normalize;
    const std::string path = dir.file("normalized.png");
    write_image(film, path, options);

    const Loaded back = load(path, OIIO::TypeDesc::UINT8);
    const auto at = [&](int x, int c) { return static_cast<int>(back.bytes[x * 4 + c]); };
    EXPECT_EQ(at(0, 0), 255);                                       // red maximum 4
    EXPECT_EQ(at(1, 1), 255);                                       // green maximum 2
    EXPECT_NEAR(at(1, 0), std::round(255 * srgb_encode(0.5)), 1);   // 2/4
    EXPECT_NEAR(at(2, 0), std::round(255 * srgb_encode(0.25)), 1);  // 1/4
    EXPECT_NEAR(at(0, 1), std::round(255 * srgb_encode(0.5)), 1);   // 1/2
    EXPECT_EQ(at(0, 2), 0);  // an all-zero channel stays zero (no division by 0)
    EXPECT_EQ(at(0, 3), 255);

    // Clamp mode would saturate the same pixels instead.
    options.range = RangeMode::Clamp;
    write_image(film, path, options);
    const Loaded clamped = load(path, OIIO::TypeDesc::UINT8);
    EXPECT_EQ(clamped.bytes[1 * 4 + 0], 255);
    EXPECT_EQ(clamped.bytes[2 * 4 + 0], 255);
}

TEST(ImageOutputTiff, SixteenBitSrgb) {
    ScopedOcioEnv env(std::nullopt);
    TempDir dir;
    const std::string path = dir.file("grey.tiff");
    write_image(grey_row({0.0f, 0.18f, 1.0f}), path, OutputOptions{});
    const Loaded back = load(path, OIIO::TypeDesc::UINT16);
    EXPECT_EQ(back.spec.format, OIIO::TypeDesc::UINT16);
    ASSERT_EQ(back.spec.nchannels, 4);
    EXPECT_EQ(back.words[0], 0);
    EXPECT_NEAR(back.words[4], std::round(65535 * srgb_encode(0.18)), 4);
    EXPECT_EQ(back.words[8], 65535);
    EXPECT_EQ(back.words[11], 65535);
}

TEST(ImageOutputJpeg, EightBitSrgbWithoutAlpha) {
    ScopedOcioEnv env(std::nullopt);
    TempDir dir;
    const std::string path = dir.file("grey.JPG");  // extensions are case-insensitive
    Film film(16, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) film.set(x, y, Vec3(0.18f, 0.18f, 0.18f));
    write_image(film, path, OutputOptions{});
    const Loaded back = load(path, OIIO::TypeDesc::UINT8);
    EXPECT_EQ(back.spec.nchannels, 3);
    EXPECT_NEAR(back.bytes[0], 118, 2);  // a flat image survives JPEG almost exactly
    EXPECT_EQ(listing(dir.path()), std::set<std::string>{"grey.JPG"});
}

TEST(ImageOutputConfig, ShippedConfigValidatesWithThreeViews) {
    OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromFile(RAYO_OCIO_CONFIG_SOURCE);
    EXPECT_NO_THROW(config->validate());
    EXPECT_EQ(config->getMajorVersion(), 2u);
    EXPECT_EQ(config->getMinorVersion(), 1u);
    ASSERT_TRUE(config->getColorSpace(OCIO::ROLE_SCENE_LINEAR));
    EXPECT_STREQ(config->getColorSpace(OCIO::ROLE_SCENE_LINEAR)->getName(),
                 "Linear Rec.709 (sRGB)");
    EXPECT_STREQ(config->getDefaultDisplay(), "sRGB");
    EXPECT_STREQ(config->getDefaultView("sRGB"), "sRGB");
    std::vector<std::string> views;
    for (int v = 0; v < config->getNumViews("sRGB"); ++v)
        views.push_back(config->getView("sRGB", v));
    EXPECT_EQ(views, (std::vector<std::string>{"sRGB", "ACES 1.0 SDR-video", "Raw"}));

    ScopedOcioEnv env(std::nullopt);
    const std::string described = describe_displays_and_views();
    EXPECT_NE(described.find("sRGB/sRGB"), std::string::npos) << described;
    EXPECT_NE(described.find("sRGB/ACES 1.0 SDR-video"), std::string::npos) << described;
    EXPECT_NE(described.find("sRGB/Raw"), std::string::npos) << described;
}

TEST(ImageOutputConfig, PathPrefersOcioThenInstalledThenSource) {
    {
        ScopedOcioEnv env(std::string("/somewhere/else/config.ocio"));
        EXPECT_EQ(ocio_config_path(), "/somewhere/else/config.ocio");
    }
    for (const std::optional<std::string>& value :
         {std::optional<std::string>(), std::optional<std::string>("")}) {
        ScopedOcioEnv env(value);
        const std::string expected = fs::exists(RAYO_OCIO_CONFIG_INSTALL) ? RAYO_OCIO_CONFIG_INSTALL
                                                                          : RAYO_OCIO_CONFIG_SOURCE;
        EXPECT_EQ(ocio_config_path(), expected);
    }
}

TEST(ImageOutputConfig, AcesViewDiffersFromPlainSrgbAndIsFinite) {
    OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromFile(RAYO_OCIO_CONFIG_SOURCE);
    const auto view_of = [&](const char* view, float linear) {
        OCIO::DisplayViewTransformRcPtr t = OCIO::DisplayViewTransform::Create();
        t->setSrc(OCIO::ROLE_SCENE_LINEAR);
        t->setDisplay("sRGB");
        t->setView(view);
        float px[4] = {linear, linear, linear, 1.0f};
        config->getProcessor(t)->getDefaultCPUProcessor()->applyRGBA(px);
        return std::vector<float>(px, px + 4);
    };
    const std::vector<float> plain = view_of("sRGB", 0.18f);
    const std::vector<float> aces = view_of("ACES 1.0 SDR-video", 0.18f);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(plain[c], srgb_encode(0.18), 1e-4);
        ASSERT_TRUE(std::isfinite(aces[c]));
        EXPECT_GT(aces[c], 0.2f);   // mid grey stays a mid tone ...
        EXPECT_LT(aces[c], 0.45f);  // ... darker than the plain encoding (the RRT's contrast)
        EXPECT_GT(std::fabs(aces[c] - plain[c]), 0.05f);
    }
    // The tone curve rolls off: a very bright value stays below 1 instead of clipping.
    const std::vector<float> bright = view_of("ACES 1.0 SDR-video", 16.0f);
    EXPECT_TRUE(std::isfinite(bright[0]));
    EXPECT_LT(bright[0], 1.0f);
    EXPECT_GT(bright[0], 0.95f);

    // The same through write_image.
    ScopedOcioEnv env(std::nullopt);
    TempDir dir;
    OutputOptions options;
    options.view = "ACES 1.0 SDR-video";
    const std::string path = dir.file("aces.png");
    write_image(grey_row({0.18f}), path, options);
    const Loaded back = load(path, OIIO::TypeDesc::UINT8);
    EXPECT_NEAR(back.bytes[0], std::lround(aces[0] * 255.0f), 1);
    EXPECT_GT(std::abs(static_cast<int>(back.bytes[0]) - 118), 5);
}

TEST(ImageOutputErrors, UnknownExtensionThrowsAndLeavesNothing) {
    TempDir dir;
    const std::string path = dir.file("out.bmp");
    try {
        write_image(grey_row({0.5f}), path, OutputOptions{});
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(e.where(), path);
        EXPECT_NE(e.message().find(".bmp"), std::string::npos) << e.message();
        EXPECT_NE(e.message().find(".exr"), std::string::npos) << e.message();
        EXPECT_NE(e.message().find(".png"), std::string::npos) << e.message();
    }
    EXPECT_THROW(write_image(grey_row({0.5f}), dir.file("noextension"), OutputOptions{}),
                 InputError);
    EXPECT_TRUE(listing(dir.path()).empty());
}

TEST(ImageOutputErrors, UnknownViewOrDisplayThrowsListingValidOnes) {
    ScopedOcioEnv env(std::nullopt);
    TempDir dir;
    const std::string path = dir.file("out.png");
    OutputOptions options;
    options.view = "Filmic";
    try {
        write_image(grey_row({0.5f}), path, options);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(e.where(), path);
        EXPECT_NE(e.message().find("Filmic"), std::string::npos) << e.message();
        EXPECT_NE(e.message().find("sRGB/ACES 1.0 SDR-video"), std::string::npos) << e.message();
        EXPECT_NE(e.message().find("sRGB/Raw"), std::string::npos) << e.message();
    }
    options.view.clear();
    options.display = "P3-DCI";
    try {
        write_image(grey_row({0.5f}), path, options);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(e.message().find("P3-DCI"), std::string::npos) << e.message();
        EXPECT_NE(e.message().find("sRGB/sRGB"), std::string::npos) << e.message();
    }
    EXPECT_TRUE(listing(dir.path()).empty());
}

TEST(ImageOutputErrors, FailedWriteKeepsTheExistingFile) {
    ScopedOcioEnv env(std::nullopt);
    TempDir dir;
    const std::string path = dir.file("keep.png");
    { std::ofstream(path) << "previous contents"; }
    OutputOptions options;
    options.view = "no such view";
    EXPECT_THROW(write_image(grey_row({0.5f}), path, options), InputError);
    EXPECT_EQ(read_text(path), "previous contents");
    EXPECT_EQ(listing(dir.path()), std::set<std::string>{"keep.png"});

    // A successful write replaces it and leaves no temporary behind.
    write_image(grey_row({0.5f}), path, OutputOptions{});
    EXPECT_NE(read_text(path), "previous contents");
    EXPECT_EQ(listing(dir.path()), std::set<std::string>{"keep.png"});
}

TEST(ImageOutputErrors, UnwritableOrMissingDirectoryThrowsAndLeavesNothing) {
    ScopedOcioEnv env(std::nullopt);
    TempDir dir;
    const fs::path locked = dir.path() / "locked";
    fs::create_directory(locked);
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
    // A privileged user ignores mode bits; /proc refuses new files to everyone.
    const fs::path unwritable = ::access(locked.c_str(), W_OK) == 0 ? fs::path("/proc") : locked;
    const Film film = grey_row({0.5f});
    for (const char* name : {"out.png", "out.exr", "out.tif", "out.jpg"}) {
        const std::string path = (unwritable / name).string();
        try {
            write_image(film, path, OutputOptions{});
            FAIL() << "expected InputError for " << path;
        } catch (const InputError& e) {
            EXPECT_EQ(e.where(), path);
            EXPECT_EQ(e.message().rfind("cannot write", 0), 0u) << e.message();
        }
    }
    // No output and no temporary ("out.*" or ".out.*"): /proc's own listing changes as
    // processes come and go, so only our names are checked.
    for (const std::string& entry : listing(unwritable)) {
        EXPECT_EQ(entry.find("out."), std::string::npos) << entry;
    }

    for (const char* name : {"missing/out.png", "missing/out.exr"}) {
        const std::string path = dir.file(name);
        EXPECT_THROW(write_image(film, path, OutputOptions{}), InputError) << path;
    }
    // A regular file where the directory should be.
    { std::ofstream(dir.file("plain_file")) << "x"; }
    EXPECT_THROW(write_image(film, dir.file("plain_file/out.png"), OutputOptions{}), InputError);
    EXPECT_EQ(listing(dir.path()), (std::set<std::string>{"locked", "plain_file"}));
    EXPECT_TRUE(listing(locked).empty());
}

TEST(ImageOutputOcioEnv, OverrideConfigIsHonoured) {
    TempDir dir;
    // A copy of the shipped config whose default view is Raw instead of sRGB.
    std::string text = read_text(RAYO_OCIO_CONFIG_SOURCE);
    const std::string from = "active_views: [sRGB, ACES 1.0 SDR-video, Raw]";
    const size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, from.size(), "active_views: [Raw, sRGB, ACES 1.0 SDR-video]");
    const std::string config_path = dir.file("override.ocio");
    { std::ofstream(config_path) << text; }

    const std::string out_dir = dir.file("out");
    fs::create_directory(out_dir);
    const std::string path = out_dir + "/raw.png";
    {
        ScopedOcioEnv env(config_path);
        EXPECT_EQ(ocio_config_path(), config_path);
        write_image(grey_row({0.18f}), path, OutputOptions{});
        const Loaded raw = load(path, OIIO::TypeDesc::UINT8);
        EXPECT_EQ(raw.bytes[0], 46);  // 0.18 * 255 = 45.9, no encoding
    }
    // Restored: the shipped config's default view applies again.
    write_image(grey_row({0.18f}), path, OutputOptions{});
    EXPECT_NEAR(load(path, OIIO::TypeDesc::UINT8).bytes[0], 118, 1);

    // A broken $OCIO is reported with the config's path; EXR output does not need OCIO.
    const std::string missing = dir.file("missing.ocio");
    ScopedOcioEnv env(missing);
    try {
        write_image(grey_row({0.18f}), out_dir + "/broken.png", OutputOptions{});
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(e.where(), missing);
    }
    EXPECT_NO_THROW(write_image(grey_row({0.18f}), out_dir + "/fine.exr", OutputOptions{}));
    EXPECT_EQ(listing(out_dir), (std::set<std::string>{"raw.png", "fine.exr"}));
}

}  // namespace
}  // namespace rayo
