// PNG files through libpng (io/png_text.h's encoding and reading; the web build has its own,
// src/web/web_png.cpp). libpng reports errors by longjmp: every call that can fail runs inside a
// function whose frame holds nothing with a destructor (the *Guarded ones below), so no C++ object
// is skipped over; the callbacks copy libpng's message into a fixed buffer.
#include "io/png_text.h"

#include <png.h>

#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <cstring>

#include "io/printable_text.h"

namespace oasis {
namespace {

// Past this many, what was ignored is counted, so a file of a million bad chunks cannot grow the
// report without bound.
constexpr size_t kMaxIgnoredReasons = 16;
// libpng's own caps, set before it reads a byte: no chunk (a text, decompressed) above 1 MiB, at
// most this many ancillary chunks kept, and a header no wider than PNG's user-limit default.
constexpr png_alloc_size_t kMaxChunkBytes = png_alloc_size_t(1) << 20;
constexpr png_uint_32 kMaxAncillaryChunks = 256;
constexpr png_uint_32 kMaxHeaderSide = 1000000;

// One libpng read or write: the structs, where the bytes are, and what went wrong.
struct Session {
    png_structp png = nullptr;
    png_infop info = nullptr;
    const std::string* input = nullptr;  // reading: the file's bytes
    size_t at = 0;
    std::string* output = nullptr;       // writing
    std::vector<std::string>* warnings = nullptr;
    size_t warningCount = 0;
    char error[256] = "";
};

void onError(png_structp png, png_const_charp message) {
    Session* session = static_cast<Session*>(png_get_error_ptr(png));
    std::snprintf(session->error, sizeof session->error, "%s", message && *message ? message : "libpng failed");
    png_longjmp(png, 1);
}

void onWarning(png_structp png, png_const_charp message) {
    Session* session = static_cast<Session*>(png_get_error_ptr(png));
    if (session->warnings && ++session->warningCount <= kMaxIgnoredReasons)
        session->warnings->push_back(printableText(message ? message : "a libpng warning"));
}

void onRead(png_structp png, png_bytep out, size_t count) {
    Session* session = static_cast<Session*>(png_get_io_ptr(png));
    if (session->input->size() - session->at < count) png_error(png, "the file ends early: it is cut");
    std::memcpy(out, session->input->data() + session->at, count);
    session->at += count;
}

void onWrite(png_structp png, png_bytep data, size_t count) {
    static_cast<Session*>(png_get_io_ptr(png))->output->append(reinterpret_cast<const char*>(data), count);
}

void onFlush(png_structp) {}

// The read session's structs with oasis's limits; false when libpng cannot make them.
bool openReader(Session& session) {
    session.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &session, onError, onWarning);
    session.info = session.png ? png_create_info_struct(session.png) : nullptr;
    if (!session.info) {
        std::snprintf(session.error, sizeof session.error, "libpng cannot start (no memory)");
        return false;
    }
    png_set_read_fn(session.png, &session, onRead);
    png_set_user_limits(session.png, kMaxHeaderSide, kMaxHeaderSide);
    png_set_chunk_malloc_max(session.png, kMaxChunkBytes);
    png_set_chunk_cache_max(session.png, kMaxAncillaryChunks);
    return true;
}

bool readInfoGuarded(Session& session) {
    if (setjmp(png_jmpbuf(session.png))) return false;
    png_read_info(session.png, session.info);
    return true;
}

// To 8-bit RGBA whatever the file holds, then every row, then the chunks after the data (their CRCs).
bool readRowsGuarded(Session& session, png_bytepp rows) {
    if (setjmp(png_jmpbuf(session.png))) return false;
    png_set_expand(session.png);
    png_set_strip_16(session.png);
    png_set_gray_to_rgb(session.png);
    png_set_add_alpha(session.png, 0xFF, PNG_FILLER_AFTER);
    png_set_interlace_handling(session.png);
    png_read_update_info(session.png, session.info);
    if (png_get_rowbytes(session.png, session.info) != size_t(png_get_image_width(session.png, session.info)) * 4)
        png_error(session.png, "libpng did not convert it to 8-bit RGBA");
    png_read_image(session.png, rows);
    png_read_end(session.png, nullptr);
    return true;
}

bool writeGuarded(Session& session, png_uint_32 width, png_uint_32 height, png_textp texts, int textCount,
                  png_bytepp rows) {
    if (setjmp(png_jmpbuf(session.png))) return false;
    png_set_write_fn(session.png, &session, onWrite, onFlush);
    png_set_IHDR(session.png, session.info, width, height, 8, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (textCount > 0) png_set_text(session.png, session.info, texts, textCount);
    png_write_info(session.png, session.info);
    png_write_image(session.png, rows);
    png_write_end(session.png, nullptr);
    return true;
}

std::string latin1ToUtf8(const char* text, size_t length) {
    std::string utf8;
    for (size_t i = 0; i < length; ++i) {
        uint8_t byte = uint8_t(text[i]);
        if (byte < 0x80) {
            utf8 += char(byte);
        } else {
            utf8 += char(0xC0 | (byte >> 6));
            utf8 += char(0x80 | (byte & 0x3F));
        }
    }
    return utf8;
}

// The texts libpng read (file order), each judged as oasis keeps them.
void collectTexts(Session& session, PngTexts& result, size_t& ignoredCount) {
    auto ignore = [&](const std::string& why) {
        if (++ignoredCount <= kMaxIgnoredReasons) result.ignored.push_back(why);
    };
    png_textp texts = nullptr;
    int count = png_get_text(session.png, session.info, &texts, nullptr);
    for (int k = 0; k < count; ++k) {
        const png_text& text = texts[k];
        std::string keyword = text.key ? text.key : "", why;
        bool international = text.compression == PNG_ITXT_COMPRESSION_NONE || text.compression == PNG_ITXT_COMPRESSION_zTXt;
        size_t length = international ? text.itxt_length : text.text_length;
        std::string name = "the text chunk '" + printableText(keyword) + "'";
        if (!validPngKeyword(keyword, &why)) ignore("a text chunk's keyword " + why);
        else if (result.texts.size() >= kMaxPngTexts) ignore(name + " is past the " + std::to_string(kMaxPngTexts) + " text chunks oasis reads");
        else if (keyword.size() + 1 + length > kMaxPngTextBytes)  // as the chunk's data counts them
            ignore(name + " holds " + std::to_string(length) + " bytes, over the " + std::to_string(kMaxPngTextBytes) + " oasis reads");
        else if (result.find(keyword)) ignore(name + " repeats the keyword (the first kept)");
        else result.texts.push_back({keyword, international ? validUtf8(std::string(text.text ? text.text : "", length))
                                                            : latin1ToUtf8(text.text ? text.text : "", length)});
    }
}

bool sizeAllowed(const PngHeader& header, std::string& error, uint32_t maxSide);

// Reads the header and the chunks before the data into `header`; false with `error`. The session
// stays open for the pixels.
bool readHeader(Session& session, PngHeader& header, std::string& error, uint32_t maxSide) {
    if (session.input->size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(session.input->data()), 0, 8) != 0) {
        error = "not a PNG file";
        return false;
    }
    session.warnings = &header.texts.ignored;
    if (!openReader(session)) {
        error = session.error;
        return false;
    }
    bool read = readInfoGuarded(session);
    // The size is judged first, as soon as IHDR is read (a file cut after it is too large before
    // it is cut); then what libpng could not read.
    header.width = png_get_image_width(session.png, session.info);
    header.height = png_get_image_height(session.png, session.info);
    if (header.width > 0 && !sizeAllowed(header, error, maxSide)) return false;
    if (!read) {
        error = std::string("not a readable PNG (") + printableText(session.error) + ")";
        return false;
    }
    size_t ignoredCount = session.warningCount;
    collectTexts(session, header.texts, ignoredCount);
    if (ignoredCount > kMaxIgnoredReasons)
        header.texts.ignored.push_back("and " + std::to_string(ignoredCount - kMaxIgnoredReasons) + " more");
    return true;
}

// False with `error` when the header's size is over `maxSide` (at most kMaxPngSide) or the
// decoded-bytes cap.
bool sizeAllowed(const PngHeader& header, std::string& error, uint32_t maxSide) {
    std::string size = std::to_string(header.width) + "x" + std::to_string(header.height);
    uint32_t limit = std::min(maxSide, kMaxPngSide);
    if (header.width > limit || header.height > limit) {
        error = "its header says " + size + " pixels; oasis reads at most " + std::to_string(limit) + " a side" +
                (limit < kMaxPngSide ? " unless --allow-large is given (then " + std::to_string(kMaxPngSide) + ")" : "");
        return false;
    }
    if (uint64_t(header.width) * header.height * 4 > kMaxPngDecodedBytes) {
        error = "its header says " + size + " pixels, more than the 1 GiB of RGBA oasis decodes";
        return false;
    }
    return true;
}

struct SessionGuard {
    Session& session;
    bool reading;
    ~SessionGuard() {
        if (reading) png_destroy_read_struct(&session.png, session.info ? &session.info : nullptr, nullptr);
        else png_destroy_write_struct(&session.png, session.info ? &session.info : nullptr);
    }
};

}  // namespace

bool encodePngBytes(const uint8_t* rgba, int width, int height, const std::vector<PngText>& texts, std::string& png,
                    std::string& error) {
    png.clear();
    if (width < 1 || height < 1) {
        error = "an empty image (" + std::to_string(width) + "x" + std::to_string(height) + ")";
        return false;
    }
    std::vector<std::string> utf8(texts.size());
    std::vector<png_text> chunks(texts.size());
    for (size_t k = 0; k < texts.size(); ++k) {
        std::string why;
        if (!validPngKeyword(texts[k].keyword, &why)) {
            error = "the PNG text keyword '" + printableText(texts[k].keyword) + "' " + why;
            return false;
        }
        utf8[k] = validUtf8(texts[k].text);
        if (texts[k].keyword.size() + utf8[k].size() + 5 > kMaxPngTextBytes) {
            error = "the PNG text '" + texts[k].keyword + "' is " + std::to_string(utf8[k].size()) + " bytes, over " +
                    std::to_string(kMaxPngTextBytes);
            return false;
        }
        chunks[k].compression = PNG_ITXT_COMPRESSION_NONE;
        chunks[k].key = const_cast<char*>(texts[k].keyword.c_str());
        chunks[k].text = const_cast<char*>(utf8[k].c_str());
        chunks[k].itxt_length = utf8[k].size();
    }
    std::vector<png_bytep> rows(static_cast<size_t>(height));
    for (int y = 0; y < height; ++y) rows[size_t(y)] = const_cast<png_bytep>(rgba + size_t(y) * size_t(width) * 4);
    Session session;
    session.output = &png;
    SessionGuard guard{session, false};
    session.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &session, onError, onWarning);
    session.info = session.png ? png_create_info_struct(session.png) : nullptr;
    if (!session.info || !writeGuarded(session, png_uint_32(width), png_uint_32(height), chunks.data(),
                                       int(chunks.size()), rows.data())) {
        error = std::string("libpng: ") + (session.error[0] ? session.error : "no memory");
        png.clear();
        return false;
    }
    return true;
}

bool readPngHeader(const std::string& png, PngHeader& header, std::string& error, uint32_t maxSide) {
    Session session;
    session.input = &png;
    SessionGuard guard{session, true};
    header = PngHeader{};
    return readHeader(session, header, error, maxSide);
}

PngTexts readPngTexts(const std::string& png) {
    PngHeader header;
    std::string error;
    if (!readPngHeader(png, header, error, kMaxPngSide) && header.texts.texts.empty())
        header.texts.ignored.push_back(error);
    return header.texts;
}

bool decodePngBytes(const std::string& png, std::vector<uint8_t>& rgba, uint32_t& width, uint32_t& height,
                    std::string& error, uint32_t maxSide) {
    Session session;
    session.input = &png;
    SessionGuard guard{session, true};
    PngHeader header;
    if (!readHeader(session, header, error, maxSide)) return false;
    width = header.width;
    height = header.height;
    rgba.assign(size_t(width) * height * 4, 0);
    std::vector<png_bytep> rows(height);
    for (uint32_t y = 0; y < height; ++y) rows[y] = rgba.data() + size_t(y) * width * 4;
    if (!readRowsGuarded(session, rows.data())) {
        error = std::string("not a readable PNG (") + printableText(session.error) + ")";
        rgba.clear();
        return false;
    }
    return true;
}

}  // namespace oasis
