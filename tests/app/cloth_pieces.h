// Test support: the pieces a cloth's intact triangles make, and the springs that join two of
// them (what the shaded view cannot show: a piece hanging by one looks as if it floats).
#pragma once

#include <cstddef>
#include <numeric>
#include <vector>

#include "sim/core/cloth.h"

namespace weft::app {

struct ClothPieces {
    std::vector<std::size_t> piece_of;  // per particle; one with no triangle is a piece alone
    std::size_t pieces_with_triangles = 0;
    std::size_t joining_springs = 0;  // springs whose ends lie in two pieces
};

inline ClothPieces cloth_pieces(const Cloth& cloth) {
    std::vector<std::size_t> parent(cloth.particle_count());
    std::iota(parent.begin(), parent.end(), std::size_t{0});
    auto root = [&](std::size_t p) {
        while (parent[p] != p) p = parent[p] = parent[parent[p]];
        return p;
    };
    std::vector<bool> in_triangle(cloth.particle_count(), false);
    for (const Triangle& t : cloth.topology().triangles) {
        parent[root(t.a)] = root(t.b);
        parent[root(t.b)] = root(t.c);
        in_triangle[t.a] = in_triangle[t.b] = in_triangle[t.c] = true;
    }
    ClothPieces pieces;
    pieces.piece_of.resize(cloth.particle_count());
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        pieces.piece_of[p] = root(p);
        if (in_triangle[p] && root(p) == p) ++pieces.pieces_with_triangles;
    }
    for (const SpringGroup& group : cloth.topology().spring_groups)
        for (const Spring& s : group.springs)
            if (pieces.piece_of[s.i] != pieces.piece_of[s.j]) ++pieces.joining_springs;
    return pieces;
}

}  // namespace weft::app
