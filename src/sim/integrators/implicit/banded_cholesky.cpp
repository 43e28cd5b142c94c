#include "sim/integrators/implicit/banded_cholesky.h"

#include <algorithm>
#include <cmath>

namespace weft {

void BandedCholesky::reset(std::size_t size, std::size_t band) {
    size_ = size;
    band_ = band;
    factor_.assign(size * (band + 1), 0.0);
}

void BandedCholesky::factor() {
    const std::size_t width = band_ + 1;
    for (std::size_t i = 0; i < size_; ++i) {
        double* row = &factor_[i * width];
        const double original = row[0];
        // Subtract the rows above that reach this one: A[i][j] - Σ_k U[k][i] U[k][j].
        for (std::size_t k = i > band_ ? i - band_ : 0; k < i; ++k) {
            const double* above = &factor_[k * width];
            const double u_ki = above[i - k];
            if (u_ki == 0.0) continue;
            const std::size_t last = std::min(k + band_, size_ - 1);
            for (std::size_t j = i; j <= last; ++j) row[j - i] -= u_ki * above[j - k];
        }
        // A pivot that is not clearly positive marks a row of the singular part (pinned):
        // it is dropped, the rest stays exact.
        if (!(row[0] > 1e-12 * original)) {
            std::fill(row, row + width, 0.0);
            continue;
        }
        const double pivot = std::sqrt(row[0]);
        row[0] = pivot;
        for (std::size_t j = 1; j < width; ++j) row[j] /= pivot;
    }
}

void BandedCholesky::solve(double* values) const {
    const std::size_t width = band_ + 1;
    // Uᵀ y = b, by rows of U: once y_i is known, take its share out of the later entries.
    for (std::size_t i = 0; i < size_; ++i) {
        const double* row = &factor_[i * width];
        if (row[0] == 0.0) {
            values[i] = 0.0;
            continue;
        }
        values[i] /= row[0];
        const std::size_t last = std::min(i + band_, size_ - 1);
        for (std::size_t j = i + 1; j <= last; ++j) values[j] -= row[j - i] * values[i];
    }
    // U x = y, from the last row up.
    for (std::size_t i = size_; i-- > 0;) {
        const double* row = &factor_[i * width];
        if (row[0] == 0.0) {
            values[i] = 0.0;
            continue;
        }
        const std::size_t last = std::min(i + band_, size_ - 1);
        double sum = values[i];
        for (std::size_t j = i + 1; j <= last; ++j) sum -= row[j - i] * values[j];
        values[i] = sum / row[0];
    }
}

}  // namespace weft
