// The image module (core/image_library.h, docs/performance.md "Fixed costs"): the rayo executable
// does not load OpenImageIO until a command reads an image or writes one in a format that needs
// it (TIFF, JPEG, --image-writer oiio; PNG and EXR are written with libpng and OpenEXR), and a
// module that cannot be loaded is a clear error that leaves no output behind. The dynamic loader's
// own log (LD_DEBUG=libs, glibc) says which libraries the process loaded.
#include <string>

#include "cli_fixture.h"

namespace rayo_test {
namespace {

class ImageModuleCli : public CliFixture {
  protected:
    // The libraries `rayo ARGS` loaded, from the dynamic loader's log (stderr with its output).
    CommandResult run_logging_libraries(const std::string& args) const {
        return run(args, "LD_DEBUG=libs");
    }
    static bool loaded_openimageio(const std::string& log) {
        return log.find("libOpenImageIO.so") != std::string::npos;
    }
    // The log is the loader's: it names the libraries rayo links (Embree is always linked).
    static bool is_loader_log(const std::string& log) {
        return log.find("libembree3.so") != std::string::npos;
    }
};

TEST_F(ImageModuleCli, CommandsWithoutImagesDoNotLoadOpenImageIO) {
    write("two.nff", kSceneNff);
    for (const std::string args :
         {"--version", "--help", "render --no-such-flag", "info two.nff"}) {
        const CommandResult r = run_logging_libraries(args);
        EXPECT_TRUE(is_loader_log(r.output)) << args << ":\n" << r.output;
        EXPECT_FALSE(loaded_openimageio(r.output)) << args;
        EXPECT_EQ(r.output.find("librayo_oiio.so"), std::string::npos) << args;
    }
}

// PNG and EXR are written with libpng and OpenEXR (core/image/image_writers.h): in memory and
// streamed, a render writing them never loads OpenImageIO.
TEST_F(ImageModuleCli, PngAndExrRendersDoNotLoadTheModule) {
    write("two.nff", kSceneNff);
    for (const std::string args :
         {"-o a.png", "-o b.exr", "--stream -o c.png", "--stream -o d.exr",
          "--half --exr-compression piz -o e.exr", "--image-writer direct -o f.png"}) {
        const CommandResult r = run_logging_libraries("render two.nff --width 30 --quiet " + args);
        ASSERT_EQ(r.exit_code, 0) << r.output;
        EXPECT_TRUE(is_loader_log(r.output)) << args;
        EXPECT_EQ(r.output.find("librayo_oiio.so"), std::string::npos) << args;
        EXPECT_FALSE(loaded_openimageio(r.output)) << args;
        const std::string out = args.substr(args.rfind(' ') + 1);
        EXPECT_EQ(read_pixels(out).size(), size_t(30) * 20 * 4) << args;
    }
}

// TIFF and JPEG, and PNG/EXR with the reference writer, go through the module.
TEST_F(ImageModuleCli, OtherFormatsAndTheReferenceWriterLoadTheModule) {
    write("two.nff", kSceneNff);
    for (const std::string args :
         {"-o a.tif", "-o b.jpg", "--stream -o c.tif", "--image-writer oiio -o d.png",
          "--image-writer oiio -o e.exr", "--image-writer oiio --stream -o f.exr"}) {
        const CommandResult r = run_logging_libraries("render two.nff --width 30 --quiet " + args);
        ASSERT_EQ(r.exit_code, 0) << r.output;
        EXPECT_NE(r.output.find("librayo_oiio.so"), std::string::npos) << args;
        EXPECT_TRUE(loaded_openimageio(r.output)) << args;
        const std::string out = args.substr(args.rfind(' ') + 1);
        EXPECT_EQ(read_pixels(out).size(), size_t(30) * 20 * 4) << args;  // RGBA as read
    }
}

TEST_F(ImageModuleCli, MissingModuleIsAClearErrorAndLeavesNoOutput) {
    write("two.nff", kSceneNff);
    const std::string module = (m_dir / "nowhere" / "librayo_oiio.so").string();
    // In memory, streamed EXR and TIFF (through the module): each fails before creating a file.
    for (const std::string args :
         {"render two.nff --width 30 -o out.tif",
          "render two.nff --width 30 --image-writer oiio -o out.png",
          "render two.nff --width 30 --image-writer oiio --stream -o out.exr",
          "render two.nff --width 30 --stream -o out.tif"}) {
        const CommandResult r = run(args, "RAYO_IMAGE_MODULE='" + module + "'");
        EXPECT_EQ(r.exit_code, 1) << r.output;
        EXPECT_NE(r.output.find("rayo: error: cannot load the image I/O module"), std::string::npos)
            << r.output;
        EXPECT_NE(r.output.find(module), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("No such file or directory"), std::string::npos) << r.output;
        EXPECT_EQ(listing(), std::set<std::string>{"two.nff"}) << args;
    }
}

// Without the module, PNG and EXR are still written.
TEST_F(ImageModuleCli, PngAndExrAreWrittenWithoutTheModule) {
    write("two.nff", kSceneNff);
    const std::string module = (m_dir / "nowhere" / "librayo_oiio.so").string();
    for (const std::string out : {"out.png", "out.exr"}) {
        const CommandResult r = run("render two.nff --width 30 --quiet -o " + out,
                                    "RAYO_IMAGE_MODULE='" + module + "'");
        EXPECT_EQ(r.exit_code, 0) << r.output;
        EXPECT_EQ(read_pixels(out).size(), size_t(30) * 20 * 4) << out;
    }
}

TEST_F(ImageModuleCli, ALibraryThatIsNotTheModuleIsRefused) {
    write("two.nff", kSceneNff);
    // A shared library every process has, without the module's entry point: found, so the
    // render runs, and refused at the write (--no-journal: no .rayo-partial kept to resume). In
    // memory the write loads it; streamed, the writer's thread does while the render runs, and
    // the failure reaches the render at its next tile or at the end.
    for (const std::string args :
         {"render two.nff --width 30 --no-journal --image-writer oiio -o out.exr",
          "render two.nff --width 30 --no-journal --image-writer oiio --stream -o out.exr",
          "render two.nff --width 30 --no-journal --stream -o out.jpg"}) {
        const CommandResult r = run(args, "RAYO_IMAGE_MODULE=libm.so.6");
        EXPECT_EQ(r.exit_code, 1) << args << ":\n" << r.output;
        EXPECT_NE(r.output.find("libm.so.6: no rayo_image_library (not rayo's image module)"),
                  std::string::npos)
            << r.output;
        EXPECT_EQ(listing(), std::set<std::string>{"two.nff"}) << args;
    }
}

}  // namespace
}  // namespace rayo_test
