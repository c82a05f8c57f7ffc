// JPEG files read with libjpeg, so a scene whose image maps are JPEGs does not pay OpenImageIO's 0.7 s load.
#include "render/jpeg_reader.h"

#include <csetjmp>
#include <cstdio>
#include <memory>

#include <jpeglib.h>

namespace wardray::render {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

struct ErrorManager {
    jpeg_error_mgr base;
    std::jmp_buf jump;
};

void on_error(j_common_ptr info) { std::longjmp(reinterpret_cast<ErrorManager*>(info->err)->jump, 1); }
void on_message(j_common_ptr, int) {}

struct JpegRows {
    JDIMENSION width = 0;
    JDIMENSION height = 0;
    bool grey = false;
    std::vector<unsigned char> bytes;  ///< height rows of width RGB bytes
};

/// Decodes a grey or YCbCr/RGB JPEG as RGB with libjpeg's default decoder settings, or returns false (an
/// error, or CMYK and other colour spaces, left to OpenImageIO). Nothing with a destructor lives in this frame
/// across setjmp.
bool read_rows(std::FILE* file, JpegRows& out) {
    jpeg_decompress_struct info;
    ErrorManager errors;
    info.err = jpeg_std_error(&errors.base);
    errors.base.error_exit = on_error;
    errors.base.emit_message = on_message;
    if (setjmp(errors.jump)) {
        jpeg_destroy_decompress(&info);
        return false;
    }
    jpeg_create_decompress(&info);
    jpeg_stdio_src(&info, file);
    jpeg_read_header(&info, TRUE);
    if (info.num_components != 1 && info.num_components != 3) {
        jpeg_destroy_decompress(&info);
        return false;
    }
    info.out_color_space = info.num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_start_decompress(&info);
    out.width = info.output_width;
    out.height = info.output_height;
    const int channels = info.output_components;
    out.grey = channels == 1;
    out.bytes.resize(static_cast<std::size_t>(out.width) * out.height * 3);
    std::vector<unsigned char>& bytes = out.bytes;
    while (info.output_scanline < info.output_height) {
        unsigned char* row = bytes.data() + static_cast<std::size_t>(info.output_scanline) * out.width * 3;
        JSAMPROW rows[1] = {row};
        jpeg_read_scanlines(&info, rows, 1);
        if (channels == 1)  // grey: spread in place, from the end
            for (JDIMENSION x = out.width; x-- > 0;) row[3 * x] = row[3 * x + 1] = row[3 * x + 2] = row[x];
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    return true;
}

}  // namespace

bool read_jpeg_rgb(const std::filesystem::path& path, int& width, int& height, std::vector<float>& rgb, bool* grey) {
    const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file) return false;
    unsigned char signature[3] = {0};
    if (std::fread(signature, 1, 3, file.get()) != 3 || signature[0] != 0xff || signature[1] != 0xd8 ||
        signature[2] != 0xff)
        return false;
    std::rewind(file.get());
    JpegRows rows;
    if (!read_rows(file.get(), rows) || rows.width == 0 || rows.height == 0) return false;
    width = static_cast<int>(rows.width);
    height = static_cast<int>(rows.height);
    if (grey) *grey = rows.grey;
    rgb.resize(rows.bytes.size());
    // As OpenImageIO converts 8-bit samples to float: the value times 1/255 in single precision.
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<float>(rows.bytes[i]) * (1.0f / 255.0f);
    return true;
}

}  // namespace wardray::render
