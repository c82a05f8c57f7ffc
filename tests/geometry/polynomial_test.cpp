// Tests of the polynomial root finder the shapes share (geometry/polynomial.h): roots to their conditioning, in
// order, one at a time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "geometry/polynomial.h"

namespace wardray::geometry {
namespace {

TEST(Polynomial, EachRootGivesPolynomialRootsOneAtATimeAndStopsWhenAsked) {
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    for (int trial = 0; trial < 500; ++trial) {
        const int degree = 2 + trial % 7;
        double c[9] = {};
        for (int i = 0; i <= degree; ++i) c[i] = u(rng);
        double all[8];
        const int n = polynomial_roots(c, degree, -3.0, 3.0, all);
        std::vector<double> visited;
        auto keep = [&](double x) {
            visited.push_back(x);
            return false;
        };
        EXPECT_FALSE(each_polynomial_root(c, degree, -3.0, 3.0, keep));
        ASSERT_EQ(static_cast<int>(visited.size()), n) << "trial " << trial;
        for (int k = 0; k < n; ++k) EXPECT_EQ(visited[k], all[k]) << "trial " << trial;
        // Stopping at the k-th root: exactly k + 1 calls, the same values.
        for (int k = 0; k < n; ++k) {
            int calls = 0;
            auto stop = [&](double x) {
                EXPECT_EQ(x, all[calls]);
                return ++calls == k + 1;
            };
            EXPECT_TRUE(each_polynomial_root(c, degree, -3.0, 3.0, stop));
            EXPECT_EQ(calls, k + 1);
        }
    }
}

TEST(Polynomial, RootsOfAQuarticWithCloseRoots) {
    // (x - 1)(x - 1.001)(x + 2)(x - 3)
    const double r[4] = {1.0, 1.001, -2.0, 3.0};
    double c[5] = {1, 0, 0, 0, 0};
    for (double root : r) {
        for (int i = 4; i > 0; --i) c[i] = c[i - 1] - root * c[i];
        c[0] = -root * c[0];
    }
    double roots[4];
    ASSERT_EQ(polynomial_roots(c, 4, -10, 10, roots), 4);
    EXPECT_NEAR(roots[0], -2.0, 1e-12);
    EXPECT_NEAR(roots[1], 1.0, 1e-10);
    EXPECT_NEAR(roots[2], 1.001, 1e-10);
    EXPECT_NEAR(roots[3], 3.0, 1e-12);
}


TEST(Polynomial, QuadraticRootsKeepTheirDigitsWhenTheyDifferByOrdersOfMagnitude) {
    // (x - 1e8)(x - 1e-8): the textbook formula loses the small root to cancellation.
    const double c[3] = {1.0, -(1e8 + 1e-8), 1.0};
    double roots[2];
    ASSERT_EQ(polynomial_roots(c, 2, -1e9, 1e9, roots), 2);
    EXPECT_NEAR(roots[0], 1e-8, 1e-22);
    EXPECT_NEAR(roots[1], 1e8, 1e-6);
    // Only the roots inside the interval, and none for a negative discriminant.
    ASSERT_EQ(polynomial_roots(c, 2, 0.5, 1e9, roots), 1);
    EXPECT_NEAR(roots[0], 1e8, 1e-6);
    const double none[3] = {1.0, 0.0, 1.0};
    EXPECT_EQ(polynomial_roots(none, 2, -10, 10, roots), 0);
}

TEST(Polynomial, RootsOfRandomPolynomialsToTheirConditioning) {
    // Polynomials built from their roots, degrees 2 to 8, roots at least 0.05 apart in [-3, 3]: each found root
    // lies within a few units of rounding, scaled by the root's condition number |sum |c_i| x^i| / |x f'(x)|.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    for (int trial = 0; trial < 2000; ++trial) {
        const int degree = 2 + trial % 7;
        std::vector<double> r;
        while (static_cast<int>(r.size()) < degree) {
            const double x = u(rng);
            bool apart = true;
            for (double y : r) apart = apart && std::fabs(x - y) >= 0.05;
            if (apart) r.push_back(x);
        }
        std::sort(r.begin(), r.end());
        double c[9] = {1, 0, 0, 0, 0, 0, 0, 0, 0};
        for (int k = 0; k < degree; ++k) {
            for (int i = k + 1; i > 0; --i) c[i] = c[i - 1] - r[k] * c[i];
            c[0] = -r[k] * c[0];
        }
        double roots[8];
        ASSERT_EQ(polynomial_roots(c, degree, -3.5, 3.5, roots), degree) << "trial " << trial;
        for (int k = 0; k < degree; ++k) {
            double slope = 1.0, magnitude = 0.0, power = 1.0;
            for (int j = 0; j < degree; ++j)
                if (j != k) slope *= r[k] - r[j];
            for (int i = 0; i <= degree; ++i, power *= std::fabs(r[k])) magnitude += std::fabs(c[i]) * power;
            const double tolerance = 64 * 2.2e-16 * magnitude / std::fabs(slope);
            EXPECT_NEAR(roots[k], r[k], tolerance) << "trial " << trial << " degree " << degree;
        }
    }
}

}  // namespace
}  // namespace wardray::geometry
