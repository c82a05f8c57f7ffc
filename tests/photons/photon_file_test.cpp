// The photon file (save_file / load_file): what is written reads back the same, and a damaged file is refused.
#include "photons/photon_file.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <sstream>
#include <string>

namespace wardray::photons {
namespace {

ShotPhotons sample_photons() {
    ShotPhotons shot;
    shot.surface = {make_photon({1.5, -2.25, 3.0}, {0.25, 0.5, 0.125}, {0, 10, 0}, 2),
                    make_photon({-1e-3, 7.0, 1e4}, {1.0, 0.0, 0.75}, {4, 4, 4}, 2)};
    shot.media = {make_photon({0.5, 0.5, 0.5}, {0.01, 0.02, 0.03}, {0, 5, -5}, -3)};
    shot.surface_offset = 2;
    shot.media_offset = -3;
    shot.spacing = 0.0125;
    return shot;
}

std::string written(const ShotPhotons& shot) {
    std::ostringstream out;
    write_photon_file(out, shot);
    return out.str();
}

void expect_same(const std::vector<Photon>& a, const std::vector<Photon>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].position, b[i].position);
        EXPECT_EQ(a[i].rgbe, b[i].rgbe);
        EXPECT_EQ(a[i].theta, b[i].theta);
        EXPECT_EQ(a[i].phi, b[i].phi);
    }
}

ShotPhotons read_back(const std::string& bytes) {
    std::istringstream in(bytes);
    return read_photon_file(in);
}

TEST(PhotonFile, WhatIsWrittenReadsBackTheSame) {
    const ShotPhotons shot = sample_photons();
    const ShotPhotons back = read_back(written(shot));
    expect_same(back.surface, shot.surface);
    expect_same(back.media, shot.media);
    EXPECT_EQ(back.surface_offset, 2);
    EXPECT_EQ(back.media_offset, -3);
    EXPECT_EQ(back.spacing, 0.0125);
    EXPECT_EQ(written(back), written(shot));
}

TEST(PhotonFile, AnEmptyPassReadsBackEmpty) {
    const ShotPhotons back = read_back(written(ShotPhotons{}));
    EXPECT_TRUE(back.surface.empty());
    EXPECT_TRUE(back.media.empty());
}

TEST(PhotonFile, DamagedFilesAreRefusedWithTheReason) {
    const std::string good = written(sample_photons());
    auto reason = [](const std::string& bytes) {
        try {
            read_back(bytes);
        } catch (const PhotonFileError& e) {
            return std::string(e.what());
        }
        return std::string("read");
    };
    EXPECT_EQ(reason("P3\n1 1\n255\n"), "not a wardray photon file (of this version)");
    EXPECT_EQ(reason(good.substr(0, good.size() - 5)), "the file is cut short");
    EXPECT_EQ(reason(good.substr(0, 30)), "the file is cut short");
    EXPECT_EQ(reason(good + "x"), "it has bytes after its photons");
    std::string huge = good;
    huge[18 + 7] = '\x7f';  // the surface count's top byte
    EXPECT_EQ(reason(huge), "its photon counts are damaged");
    std::string nan = good;
    const float not_a_number = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(nan.data() + 18 + 8 + 8 + 4 + 4 + 8, &not_a_number, sizeof not_a_number);  // the first x
    EXPECT_EQ(reason(nan), "a photon's position is not a finite number");
}

}  // namespace
}  // namespace wardray::photons
