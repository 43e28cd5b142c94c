// A symmetric positive semidefinite band matrix, factored as A = Uᵀ U (Cholesky) and solved
// exactly: the coarsest level of the implicit solve's preconditioner (implicit_multilevel.h).
//
// Why exact there: the coarse levels' block-Jacobi corrections see one aggregate at a time,
// and the coarsest carries the sheet-wide modes; solving it exactly instead took the 128²
// cloth's conjugate gradient from 27 to 18 iterations a step. A grid of n nodes a side,
// numbered row by row, couples each unknown to those at most (n + 1) nodes later, so its
// band is narrow and the factor costs n_unknowns × band² — a few thousand operations on an
// 8 x 8 level, nothing beside one fine matrix product.
//
// Rows whose pivot vanishes (an aggregate of pinned particles has an all-zero block and no
// couplings) are left out: their solution is zero, as the filtered system asks.
#pragma once

#include <cstddef>
#include <vector>

namespace weft {

class BandedCholesky {
  public:
    // Clears to an n x n zero matrix with `band` entries right of the diagonal.
    void reset(std::size_t size, std::size_t band);
    // A[row][column] += value, for row <= column <= row + band (the upper triangle).
    void add(std::size_t row, std::size_t column, double value) {
        factor_[row * (band_ + 1) + (column - row)] += value;
    }
    // Factors in place; call once after the last add().
    void factor();
    // x = A⁻¹ b in place (b in, x out), A as factored.
    void solve(double* values) const;

    std::size_t size() const { return size_; }

  private:
    std::size_t size_ = 0, band_ = 0;
    std::vector<double> factor_;  // row i holds U[i][i .. i + band]
};

}  // namespace weft
