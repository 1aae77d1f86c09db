// libFuzzer target for the resume journal (core/image/partial_render.cpp PartialRender::resume:
// what `rayo render --resume` reads from OUTPUT.rayo-partial). The input is written as the partial
// render of a 40 × 16 render in tiles of 16 (three tiles, the last one 8 pixels wide) and
// resumed with a fixed fingerprint. A refusal must be rayo::InputError. An accepted journal must
// be consistent with the format as docs/high-resolution.md describes it, read here independently
// of the reader: the tiles it counts done are exactly the records whose header (magic, index,
// pixel count, checksum) and pixels (checksum) are whole and valid in their slots; the tiles it
// replays are those, in tile order, with the pixels the file holds. The missing tiles are then
// rendered into it (deterministic pixels) through the recording sink, and a second resume must
// find every tile, the old ones unchanged.
//
// Seeds (fuzz/corpus/journal/) are journals this code writes: run the fuzzer with
// RAYO_JOURNAL_SEEDS=DIR to write a valid journal of two tiles and of three, and truncated and
// corrupted variants of them, into DIR (then it exits).
#include <sys/stat.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/image/partial_render.h"
#include "core/tile_grid.h"
#include "fuzz/fuzz_files.h"
#include "fuzz/scene_invariants.h"

namespace {

constexpr int kWidth = 40, kHeight = 16, kTileSize = 16;  // three tiles: 16, 16 and 8 wide
constexpr size_t kRecordHeaderBytes = 32;
constexpr uint64_t kRecordMagic = 0x454c4954'4f594152ULL;  // "RAYOTILE", little-endian

const rayo::RenderFingerprint& fingerprint() {
    static const rayo::RenderFingerprint entries = {
        {"rayo version", "fuzz"},
        {"scene contents", "96 bytes, checksum 5f3c2a9e01b7d4c8"},
        {"resolution", "40x16"},
        {"spp", "1"},
        {"file /tmp/texture.png", "70 bytes, modified 1700000000000000000 ns"},
    };
    return entries;
}

std::string output_path() {
    return (rayo::fuzz::scratch_dir() / "journal.exr").string();
}

// Deterministic pixels of tile `index` for the tiles the fuzzer renders.
std::vector<float> pixels_of(const rayo::Tile& tile, float base) {
    std::vector<float> rgba(tile.pixel_count() * 4);
    for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = base + float(tile.index) + float(i) / 64.0f;
    return rgba;
}

// A sink that keeps what it is given.
struct Collector : rayo::TileSink {
    std::vector<int> order;
    std::vector<std::vector<float>> pixels{size_t(3)};
    void write_tile(const rayo::Tile& tile, const float* rgba) override {
        order.push_back(tile.index);
        pixels[size_t(tile.index)].assign(rgba, rgba + tile.pixel_count() * 4);
    }
};

uint64_t le64(const std::string& b, size_t at) {
    uint64_t v = 0;
    std::memcpy(&v, b.data() + at, 8);
    return v;
}
uint32_t le32(const std::string& b, size_t at) {
    uint32_t v = 0;
    std::memcpy(&v, b.data() + at, 4);
    return v;
}

// The format, read independently of PartialRender: the header's size from its first line, and
// per tile whether its slot holds a valid record (with the record's pixels). Only consulted for
// journals the reader accepted, so the fingerprint is not parsed here.
struct Expected {
    size_t header_bytes = 0;
    std::vector<bool> done;
    std::vector<std::vector<float>> pixels;
};

Expected expected_of(const std::string& bytes, const rayo::TileGrid& grid) {
    Expected e;
    const std::string magic = "rayo partial render 1 ";
    rayo::fuzz::expect(bytes.compare(0, magic.size(), magic) == 0,
                       "journal accepted without its magic line");
    e.header_bytes = std::strtoull(bytes.c_str() + magic.size(), nullptr, 10);
    rayo::fuzz::expect(e.header_bytes >= 4096 && e.header_bytes % 4096 == 0 &&
                           e.header_bytes <= (size_t(1) << 20) && e.header_bytes <= bytes.size(),
                       "journal accepted with a header size outside the format");
    const size_t slot = kRecordHeaderBytes + size_t(kTileSize) * kTileSize * 16;
    e.done.assign(size_t(grid.tile_count()), false);
    e.pixels.resize(size_t(grid.tile_count()));
    for (int index = 0; index < grid.tile_count(); ++index) {
        const rayo::Tile tile = grid.tile(index);
        const size_t at = e.header_bytes + size_t(index) * slot;
        const size_t pixel_bytes = tile.pixel_count() * 16;
        if (at + kRecordHeaderBytes + pixel_bytes > bytes.size()) continue;
        if (le64(bytes, at) != kRecordMagic || le32(bytes, at + 8) != uint32_t(index) ||
            le32(bytes, at + 12) != tile.pixel_count() ||
            le64(bytes, at + 24) != rayo::checksum64(bytes.data() + at, 24)) {
            continue;
        }
        if (le64(bytes, at + 16) !=
            rayo::checksum64(bytes.data() + at + kRecordHeaderBytes, pixel_bytes)) {
            continue;
        }
        e.done[size_t(index)] = true;
        e.pixels[size_t(index)].resize(tile.pixel_count() * 4);
        std::memcpy(e.pixels[size_t(index)].data(), bytes.data() + at + kRecordHeaderBytes,
                    pixel_bytes);
    }
    return e;
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

std::string read_all(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Writes a journal of the given tiles with PartialRender itself and returns its bytes.
std::string written_journal(const std::vector<int>& tiles) {
    const rayo::TileGrid grid(kWidth, kHeight, kTileSize);
    const std::string output = output_path();
    std::remove(rayo::partial_render_path(output).c_str());
    {
        auto partial = rayo::PartialRender::create(output, grid, fingerprint());
        Collector inner;
        auto sink = partial->recording_sink(inner);
        sink->begin(grid);
        for (int index : tiles) {
            const rayo::Tile tile = grid.tile(index);
            sink->write_tile(tile, pixels_of(tile, 0.25f).data());
        }
        partial->flush();
    }
    std::string bytes = read_all(rayo::partial_render_path(output));
    std::remove(rayo::partial_render_path(output).c_str());
    return bytes;
}

void write_seeds(const std::string& dir) {
    const std::string two = written_journal({0, 2});
    const std::string three = written_journal({0, 1, 2});
    const size_t header = 4096, slot = kRecordHeaderBytes + size_t(kTileSize) * kTileSize * 16;
    auto seed = [&](const std::string& name, const std::string& bytes) {
        rayo::fuzz::write_file(dir + "/" + name, bytes);
    };
    seed("two_tiles", two);
    seed("three_tiles", three);
    seed("cut_in_second_record", three.substr(0, header + slot + 1000));
    seed("cut_in_header", three.substr(0, 2000));
    seed("header_only", three.substr(0, header));
    std::string flipped = three;
    flipped[header + kRecordHeaderBytes + 77] ^= 0x10;  // a pixel of tile 0: its checksum fails
    seed("pixel_flipped", flipped);
    std::string index = three;
    index[header + slot + 8] = 2;  // tile 1's record says tile 2
    seed("wrong_index", index);
    std::string size = three;
    size.replace(size.find("4096"), 4, "8192");  // the header's size: slots moved
    seed("header_size_8192", size);
    std::string spp = two;
    spp.replace(spp.find("spp: 1"), 6, "spp: 2");  // another render's fingerprint
    seed("other_spp", spp);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    if (const char* dir = std::getenv("RAYO_JOURNAL_SEEDS")) {
        write_seeds(dir);
        std::exit(0);
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const rayo::TileGrid grid(kWidth, kHeight, kTileSize);
    const std::string output = output_path();
    const std::string journal = rayo::partial_render_path(output);
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    rayo::fuzz::write_file(journal, bytes);
    std::unique_ptr<rayo::PartialRender> partial;
    try {
        partial = rayo::PartialRender::resume(output, grid, fingerprint());
    } catch (const rayo::InputError&) {
        std::remove(journal.c_str());
        return 0;
    }
    // Accepted: what it found against the format.
    const Expected expected = expected_of(bytes, grid);
    int done = 0;
    std::vector<int> missing;
    for (int index = 0; index < grid.tile_count(); ++index) {
        if (expected.done[size_t(index)]) {
            ++done;
        } else {
            missing.push_back(index);
        }
    }
    rayo::fuzz::expect(partial->tile_count() == grid.tile_count(), "journal: tile count");
    rayo::fuzz::expect(partial->tiles_done() == done, "journal: tiles done differ from the file's");
    rayo::fuzz::expect(partial->missing_tiles() == missing, "journal: missing tiles differ");
    // Replayed as a render would (the recording sink's begin), then completed.
    Collector replayed;
    {
        auto sink = partial->recording_sink(replayed);
        sink->begin(grid);
        std::vector<int> order;
        for (int index = 0; index < grid.tile_count(); ++index) {
            if (expected.done[size_t(index)]) order.push_back(index);
        }
        rayo::fuzz::expect(replayed.order == order, "journal: replayed tiles differ");
        for (int index : order) {
            rayo::fuzz::expect(
                same_bits(replayed.pixels[size_t(index)], expected.pixels[size_t(index)]),
                "journal: replayed pixels differ from the file's");
        }
        for (int index : missing) {
            const rayo::Tile tile = grid.tile(index);
            sink->write_tile(tile, pixels_of(tile, 0.5f).data());
        }
        sink->finish();
        rayo::fuzz::expect(partial->failure().empty(),
                           "journal: writing the missing tiles failed: " + partial->failure());
        rayo::fuzz::expect(partial->tiles_done() == grid.tile_count(),
                           "journal: not every tile done after the render");
    }
    partial.reset();
    // Resumed again: every tile, the earlier ones unchanged, the new ones as rendered.
    try {
        partial = rayo::PartialRender::resume(output, grid, fingerprint());
    } catch (const rayo::InputError& e) {
        rayo::fuzz::violated(std::string("journal: completed journal refused: ") + e.what());
    }
    rayo::fuzz::expect(partial->tiles_done() == grid.tile_count(),
                       "journal: completed journal lacks tiles");
    Collector again;
    partial->recording_sink(again)->begin(grid);
    for (int index = 0; index < grid.tile_count(); ++index) {
        const rayo::Tile tile = grid.tile(index);
        const std::vector<float>& want =
            expected.done[size_t(index)] ? expected.pixels[size_t(index)] : pixels_of(tile, 0.5f);
        rayo::fuzz::expect(same_bits(again.pixels[size_t(index)], want),
                           "journal: tile " + std::to_string(index) + " changed on resume");
    }
    partial->remove();
    partial.reset();
    std::remove(journal.c_str());
    return 0;
}
