// The coarsest level's exact solve (sim/banded_cholesky.h) against an independent truth: a
// band matrix built as Bᵀ B + I from a random banded B is symmetric positive definite, so
// A x = b has one solution; b is made from a chosen x and the solve must give it back.
#include "sim/integrators/implicit/banded_cholesky.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace weft {
namespace {

// A dense copy of a random SPD matrix with `band` entries right of the diagonal (B upper
// triangular with half the band, so Bᵀ B reaches exactly `band`).
std::vector<double> random_band_matrix(std::size_t size, std::size_t band, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> entry(-1.0, 1.0);
    const std::size_t half = band / 2;
    std::vector<double> b(size * size, 0.0), a(size * size, 0.0);
    for (std::size_t i = 0; i < size; ++i)
        for (std::size_t j = i; j < size && j <= i + half; ++j) b[i * size + j] = entry(random);
    for (std::size_t i = 0; i < size; ++i)
        for (std::size_t j = 0; j < size; ++j) {
            double sum = i == j ? 1.0 : 0.0;
            for (std::size_t k = 0; k < size; ++k) sum += b[k * size + i] * b[k * size + j];
            a[i * size + j] = sum;
        }
    return a;
}

std::vector<double> times(const std::vector<double>& a, const std::vector<double>& x) {
    const std::size_t size = x.size();
    std::vector<double> y(size, 0.0);
    for (std::size_t i = 0; i < size; ++i)
        for (std::size_t j = 0; j < size; ++j) y[i] += a[i * size + j] * x[j];
    return y;
}

void load(BandedCholesky& exact, const std::vector<double>& a, std::size_t size, std::size_t band) {
    exact.reset(size, band);
    for (std::size_t i = 0; i < size; ++i)
        for (std::size_t j = i; j < size && j <= i + band; ++j) exact.add(i, j, a[i * size + j]);
    exact.factor();
}

TEST(BandedCholesky, SolvesABandMatrixExactly) {
    for (const std::size_t band : {0u, 1u, 6u, 29u}) {
        const std::size_t size = 60;
        const std::vector<double> a =
            random_band_matrix(size, band, static_cast<unsigned>(7 + band));
        std::vector<double> x(size);
        for (std::size_t i = 0; i < size; ++i) x[i] = std::sin(0.3 * static_cast<double>(i));
        std::vector<double> values = times(a, x);
        BandedCholesky exact;
        load(exact, a, size, band);
        exact.solve(values.data());
        for (std::size_t i = 0; i < size; ++i) EXPECT_NEAR(values[i], x[i], 1e-10) << band;
    }
}

// A pinned aggregate's rows and columns are all zero: its unknowns come out zero and the
// rest of the system is solved exactly, as if those rows were not there.
TEST(BandedCholesky, LeavesOutRowsThatAreZero) {
    const std::size_t size = 40, band = 8;
    std::vector<double> a = random_band_matrix(size, band, 3);
    const std::vector<std::size_t> pinned = {0, 17, 18, 39};
    std::vector<double> x(size);
    for (std::size_t i = 0; i < size; ++i) x[i] = 1.0 + 0.1 * static_cast<double>(i);
    for (const std::size_t p : pinned) {
        for (std::size_t k = 0; k < size; ++k) a[p * size + k] = a[k * size + p] = 0.0;
        x[p] = 0.0;
    }
    std::vector<double> values = times(a, x);
    BandedCholesky exact;
    load(exact, a, size, band);
    exact.solve(values.data());
    for (std::size_t i = 0; i < size; ++i) EXPECT_NEAR(values[i], x[i], 1e-10) << i;
}

}  // namespace
}  // namespace weft
