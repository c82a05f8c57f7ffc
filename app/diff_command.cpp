// `wardray diff`: rRMSE, bad-pixel fraction and non-finite pixels of an image against a reference.
#include "app/diff_command.h"

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "render/film.h"
#include "render/image_metrics.h"

namespace wardray::app {

namespace {

constexpr const char* kUsage =
    "usage: wardray diff IMAGE REFERENCE [--json] [-o DIFFERENCE.png]\n"
    "  prints rRMSE, the bad-pixel fraction and the count of NaN/infinite pixels of IMAGE against REFERENCE\n"
    "  (linear images: .hdr .exr; 8-bit files are decoded from sRGB). -o writes a false-colour difference\n"
    "  image: black where the two agree, blue -> green at the bad-pixel tolerance -> red at twice it,\n"
    "  magenta for non-finite pixels, with the scale drawn as a strip along the bottom.\n";

// The difference image with a strip below it showing the colour scale from 0 to twice the tolerance.
render::Film with_scale_strip(const render::Film& difference) {
    const int strip = std::max(4, difference.height() / 16);
    render::Film out(difference.width(), difference.height() + strip);
    for (int y = 0; y < difference.height(); ++y)
        for (int x = 0; x < difference.width(); ++x) out.set_pixel(x, y, difference.pixel(x, y));
    // The strip is itself a difference image of a ramp against a constant reference.
    render::Film ramp(difference.width(), 1), flat(difference.width(), 1);
    for (int x = 0; x < difference.width(); ++x) {
        // With Y_R = mean(Y_R) = 1 the tolerance is 0.1 + 0.01 = 0.11: the ramp runs from 0 to twice that.
        const double difference_y = 0.22 * x / std::max(1, difference.width() - 1);
        flat.set_pixel(x, 0, {1.0, 1.0, 1.0});
        ramp.set_pixel(x, 0, Vec3{1.0, 1.0, 1.0} * (1.0 + difference_y));
    }
    const render::Film scale = render::difference_image(ramp, flat);
    for (int y = difference.height(); y < out.height(); ++y)
        for (int x = 0; x < difference.width(); ++x) out.set_pixel(x, y, scale.pixel(x, 0));
    return out;
}

}  // namespace

int run_diff_command(const std::vector<std::string>& args) {
    std::vector<std::string> files;
    bool json = false;
    std::optional<std::string> output;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--json") {
            json = true;
        } else if (args[i] == "-o" || args[i] == "--output") {
            if (i + 1 >= args.size()) {
                std::cerr << "wardray diff: -o needs a file name\n" << kUsage;
                return 2;
            }
            output = args[++i];
        } else if (args[i] == "--help" || args[i] == "-h") {
            std::cout << kUsage;
            return 0;
        } else if (!args[i].empty() && args[i][0] == '-') {
            std::cerr << "wardray diff: unknown option '" << args[i] << "'\n" << kUsage;
            return 2;
        } else {
            files.push_back(args[i]);
        }
    }
    if (files.size() != 2) {
        std::cerr << "wardray diff: expected two images, got " << files.size() << "\n" << kUsage;
        return 2;
    }
    std::string error;
    const auto image = render::read_image(files[0], error);
    if (!image) {
        std::cerr << "wardray diff: error: " << error << "\n";
        return 1;
    }
    const auto reference = render::read_image(files[1], error);
    if (!reference) {
        std::cerr << "wardray diff: error: " << error << "\n";
        return 1;
    }
    const auto cmp = render::compare_images(*image, *reference);
    if (!cmp) {
        std::cerr << "wardray diff: error: the images differ in size (" << image->width() << "x" << image->height()
                  << " against " << reference->width() << "x" << reference->height() << ")\n";
        return 1;
    }
    if (output) {
        const render::Film difference = with_scale_strip(render::difference_image(*image, *reference));
        const render::ImageFormat format = render::format_from_extension(*output).value_or(render::ImageFormat::Png);
        if (auto e = render::write_image(difference, *output, format)) {
            std::cerr << "wardray diff: error: " << *e << "\n";
            return 1;
        }
    }
    if (json) {
        nlohmann::json j = {{"image", files[0]},
                            {"reference", files[1]},
                            {"rrmse", cmp->rrmse},
                            {"bad_pixel_fraction", cmp->bad_pixel_fraction},
                            {"non_finite_pixels", cmp->non_finite},
                            {"pixels", cmp->pixels}};
        std::cout << j.dump(2) << "\n";
    } else {
        std::printf("rRMSE %.4f %%  bad pixels %.4f %%  non-finite %llu  (%llu pixels)\n", 100.0 * cmp->rrmse,
                    100.0 * cmp->bad_pixel_fraction, static_cast<unsigned long long>(cmp->non_finite),
                    static_cast<unsigned long long>(cmp->pixels));
    }
    return 0;
}

}  // namespace wardray::app
