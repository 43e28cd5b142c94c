// The bodies of the batched lighting (surface_shading.h), included by each build of it
// inside an unnamed namespace: surface_shading.cpp (any x86-64) and
// surface_shading_avx512.cpp. Plain loops of branch-free arithmetic over arrays, which the
// compiler vectorises for whichever instruction set the including file is built with; no
// build contracts a multiply and an add (-ffp-contract=off), so all give the same bits.

void shade_lanes_body(const PreparedLighting& lighting, ShadingLanes& lanes, int count) {
    const float light_x = lighting.to_light.x, light_y = lighting.to_light.y,
                light_z = lighting.to_light.z;
    // The unit normal on the side seen, and the three light terms. Each choice selects
    // between values computed either way, so the loop has no branch.
    for (int i = 0; i < count; ++i) {
        const float front = lanes.front[i];
        const float ex = lanes.eye_x[i], ey = lanes.eye_y[i], ez = lanes.eye_z[i];
        const float nx0 = lanes.normal_x[i], ny0 = lanes.normal_y[i], nz0 = lanes.normal_z[i];
        const float length_squared = nx0 * nx0 + ny0 * ny0 + nz0 * nz0;
        const float inverse_length = 1.0f / std::sqrt(length_squared);
        // A vanishing normal (a vertex of only degenerate triangles) is lit as if facing
        // the eye; two-sided, the back is lit through its own (flipped) normal.
        const bool usable = length_squared > 1e-24f;
        const bool seen_front = front != 0.0f;
        float nx = usable ? nx0 * inverse_length : (seen_front ? ex : -ex);
        float ny = usable ? ny0 * inverse_length : (seen_front ? ey : -ey);
        float nz = usable ? nz0 * inverse_length : (seen_front ? ez : -ez);
        nx = seen_front ? nx : -nx;
        ny = seen_front ? ny : -ny;
        nz = seen_front ? nz : -nz;
        lanes.lambert[i] = std::max(nx * light_x + ny * light_y + nz * light_z, 0.0f);
        const float hx = light_x + ex, hy = light_y + ey, hz = light_z + ez;
        const float halfway_squared = hx * hx + hy * hy + hz * hz;
        lanes.halfway_squared[i] = halfway_squared;
        lanes.n_dot_h[i] = (nx * hx + ny * hy + nz * hz) / std::sqrt(halfway_squared);
        lanes.fill[i] = std::max(nx * ex + ny * ey + nz * ez, 0.0f);
    }

    // The highlight's power of n·h: by squaring for a whole exponent — bit by bit over all
    // lanes, the same products in the same order as one pixel's loop — else std::pow.
    if (lighting.integer_shininess >= 0) {
        float* power = lanes.highlight;
        float squares[ShadingLanes::capacity];
        for (int i = 0; i < count; ++i) {
            power[i] = 1.0f;
            squares[i] = lanes.n_dot_h[i];
        }
        for (int n = lighting.integer_shininess; n > 0; n >>= 1) {
            if (n & 1)
                for (int i = 0; i < count; ++i) power[i] *= squares[i];
            for (int i = 0; i < count; ++i) squares[i] *= squares[i];
        }
    } else {
        for (int i = 0; i < count; ++i)
            lanes.highlight[i] = std::pow(lanes.n_dot_h[i], lighting.shininess);
    }

    const float strength = lighting.specular_strength, cutoff = lighting.specular_cutoff;
    const glm::vec3 ambient = lighting.ambient, light = lighting.light, fill = lighting.eye_fill;
    for (int i = 0; i < count; ++i) {
        // The highlight where the light reaches the surface and n·h clears the cutoff.
        const bool lit = lanes.lambert[i] > 0.0f && strength > 0.0f &&
                         lanes.halfway_squared[i] > 0.0f && lanes.n_dot_h[i] > cutoff;
        const float specular = lit ? strength * lanes.highlight[i] : 0.0f;
        const float lambert = lanes.lambert[i], eye_fill = lanes.fill[i];
        lanes.lit_r[i] = lanes.base_r[i] * (ambient.r + light.r * lambert + fill.r * eye_fill) +
                         light.r * specular;
        lanes.lit_g[i] = lanes.base_g[i] * (ambient.g + light.g * lambert + fill.g * eye_fill) +
                         light.g * specular;
        lanes.lit_b[i] = lanes.base_b[i] * (ambient.b + light.b * lambert + fill.b * eye_fill) +
                         light.b * specular;
    }
}

void shade_batch_body(const PreparedSurface& surface, const SurfaceBatch& batch,
                      ShadingLanes& lanes, Rgba8* colours) {
    const int count = batch.count;
    // The base colour: the vertex colours, or the style's colour for the side seen; then the
    // pattern's factor.
    if (batch.colour[0] != nullptr) {
        for (int i = 0; i < count; ++i) {
            lanes.base_r[i] = batch.colour[0][i];
            lanes.base_g[i] = batch.colour[1][i];
            lanes.base_b[i] = batch.colour[2][i];
        }
    } else {
        const glm::vec3 front = surface.front_colour, back = surface.back_colour;
        for (int i = 0; i < count; ++i) {
            const bool seen_front = batch.front[i] != 0.0f;
            lanes.base_r[i] = seen_front ? front.r : back.r;
            lanes.base_g[i] = seen_front ? front.g : back.g;
            lanes.base_b[i] = seen_front ? front.b : back.b;
        }
    }
    if (batch.uv[0] != nullptr) {
        const SurfacePattern pattern = surface.pattern;
        const float frequency = surface.pattern_frequency, contrast = surface.pattern_contrast;
        for (int i = 0; i < count; ++i) {
            const float factor =
                pattern_lane(pattern, frequency, contrast, batch.uv[0][i], batch.uv[1][i]);
            lanes.base_r[i] *= factor;
            lanes.base_g[i] *= factor;
            lanes.base_b[i] *= factor;
        }
    }
    const glm::vec3 eye = surface.eye;
    for (int i = 0; i < count; ++i) {
        lanes.normal_x[i] = batch.normal[0][i];
        lanes.normal_y[i] = batch.normal[1][i];
        lanes.normal_z[i] = batch.normal[2][i];
        lanes.front[i] = batch.front[i];
        // The unit vector to the eye (zero at the eye itself).
        const float tx = eye.x - batch.position[0][i];
        const float ty = eye.y - batch.position[1][i];
        const float tz = eye.z - batch.position[2][i];
        const float distance_squared = tx * tx + ty * ty + tz * tz;
        const float inverse_distance = 1.0f / std::sqrt(distance_squared);
        const bool away = distance_squared > 0.0f;
        lanes.eye_x[i] = away ? tx * inverse_distance : 0.0f;
        lanes.eye_y[i] = away ? ty * inverse_distance : 0.0f;
        lanes.eye_z[i] = away ? tz * inverse_distance : 0.0f;
    }
    shade_lanes_body(surface.lighting, lanes, count);
    // Rounded to 8 bits and packed as the framebuffer lays out a pixel (r, g, b, a in
    // ascending addresses: a little-endian word), over the whole batch; then one 32-bit
    // store per pixel, in order.
    static_assert(sizeof(Rgba8) == 4 && std::endian::native == std::endian::little);
    std::uint32_t packed[ShadingLanes::capacity];
    for (int i = 0; i < count; ++i) {
        packed[i] = std::uint32_t{to_channel(lanes.lit_r[i])} |
                    std::uint32_t{to_channel(lanes.lit_g[i])} << 8 |
                    std::uint32_t{to_channel(lanes.lit_b[i])} << 16 | std::uint32_t{255} << 24;
    }
    for (int i = 0; i < count; ++i)
        std::memcpy(static_cast<void*>(colours + batch.pixels[i]), packed + i, sizeof(Rgba8));
}
