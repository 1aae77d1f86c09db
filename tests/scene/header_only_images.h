#pragma once
// Image files whose valid headers declare sizes their bytes do not hold: a few dozen bytes that
// say 100000 × 100000, for the limits checked from the header before a pixel is decoded
// (docs/limits.md, "Memory from small files"; issue "Robustness, round three", items 1 and 11).
// The scene tests and the CLI's bad-input catalogue both write them.
#include <cstdint>
#include <string>

namespace rayo_test {

// CRC-32 (ISO 3309, as PNG chunks use it).
inline uint32_t png_crc32(const std::string& bytes) {
    uint32_t crc = 0xFFFFFFFFu;
    for (const unsigned char byte : bytes) {
        crc ^= byte;
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

inline std::string big_endian32(uint32_t v) {
    return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
            static_cast<char>(v)};
}

inline std::string png_chunk(const std::string& type, const std::string& data) {
    return big_endian32(static_cast<uint32_t>(data.size())) + type + data +
           big_endian32(png_crc32(type + data));
}

// A PNG whose valid header declares width × height 8-bit RGB (grey: one channel), with one byte
// of pixel data.
inline std::string png_header_only(uint32_t width, uint32_t height, bool grey = false) {
    const std::string ihdr = big_endian32(width) + big_endian32(height) +
                             std::string(grey ? "\x08\x00\x00\x00\x00" : "\x08\x02\x00\x00\x00", 5);
    // One IDAT chunk (libpng reads up to the first): a zlib stream of one stored zero byte.
    const std::string idat("\x78\x01\x01\x01\x00\xfe\xff\x00\x00\x01\x00\x01", 12);
    return std::string("\x89PNG\r\n\x1a\n", 8) + png_chunk("IHDR", ihdr) + png_chunk("IDAT", idat) +
           png_chunk("IEND", "");
}

// A baseline JPEG (ITU-T T.81) whose header declares width × height grey (each at most 65535),
// with one byte of entropy-coded data: SOI, a quantisation table, SOF0, one DC and one AC
// Huffman table of a single code each, SOS, EOI. libjpeg reads the header through SOS, so every
// marker up to it must be there.
inline std::string jpeg_header_only(uint16_t width, uint16_t height) {
    const auto segment = [](unsigned char marker, const std::string& data) {
        const size_t length = data.size() + 2;
        return std::string{'\xff', static_cast<char>(marker), static_cast<char>(length >> 8),
                           static_cast<char>(length & 0xff)} +
               data;
    };
    const std::string sixteen_bit_size{static_cast<char>(height >> 8), static_cast<char>(height),
                                       static_cast<char>(width >> 8), static_cast<char>(width)};
    // One code of length 1 for symbol 0: a DC difference of 0, or the AC end of block.
    const std::string one_code = std::string(1, '\x01') + std::string(15, '\0') + '\0';
    return std::string("\xff\xd8", 2) +                                     // SOI
           segment(0xdb, std::string(1, '\0') + std::string(64, '\x01')) +  // DQT 0
           segment(0xc0, '\x08' + sixteen_bit_size + std::string("\x01\x01\x11\x00", 4)) +
           segment(0xc4, '\x00' + one_code) +                           // DHT DC 0
           segment(0xc4, '\x10' + one_code) +                           // DHT AC 0
           segment(0xda, std::string("\x01\x01\x00\x00\x3f\x00", 6)) +  // SOS
           std::string("\x00\xff\xd9", 3);                              // data, EOI
}

}  // namespace rayo_test
