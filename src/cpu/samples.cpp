// SPDX-License-Identifier: MIT
// Anti-aliasing (docs/spec.md §11) on the CPU: supersampling, every sample
// shaded. The vertex and setup stages have run once for the frame (setup
// binned each triangle to the bands its samples may touch); each band is
// rasterized and lit once per sample, the rasterizer moving the triangles by
// the sample's offset (SamplePass) and the fragment stage lighting along
// the samples' rays, and the samples' clamped light is summed in the band's
// own rows. No buffer of the whole image per sample: a band's sums are
// band_height rows. The sums are resolved (mean, gamma, 8 bits) once all
// samples are in.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "cpu/pipeline.hpp"

namespace litkit {

namespace {

// docs/spec.md §11: L_k clamped to [0, 1] (NaN counts as 0, as the encoder
// has it).
inline float clamped(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }

// The columns of a band row that some sample so far has lit: the band's
// sums hold [begin, end) only; every sample of the others saw the
// background.
struct SampledColumns {
    int begin, end;
};

// One sample of a row (`before` samples came before it) into the band's
// sums at `offset`: the lit columns' clamped light, and a count of
// background samples for the others.
void accumulate_row(const kernels::Kernels& kernels, BandScratch& s, std::size_t offset,
                    const LitRow& lit, int before, SampledColumns& columns) {
    float* const r = s.sum_r.data() + offset;
    float* const g = s.sum_g.data() + offset;
    float* const b = s.sum_b.data() + offset;
    std::uint8_t* const background = s.background_samples.data() + offset;
    auto count_background = [&](int from, int to) {
        for (int x = from; x < to; ++x) ++background[x];
    };
    if (lit.begin >= lit.end) {
        count_background(columns.begin, columns.end);
        return;
    }
    // Columns new to the sums: every sample before this one saw the background there.
    auto open = [&](int from, int to) {
        std::fill(r + from, r + to, 0.0f);
        std::fill(g + from, g + to, 0.0f);
        std::fill(b + from, b + to, 0.0f);
        std::fill(background + from, background + to, static_cast<std::uint8_t>(before));
    };
    if (columns.begin >= columns.end) {
        open(lit.begin, lit.end);
        columns = {lit.begin, lit.end};
    } else {
        if (lit.begin < columns.begin) open(lit.begin, columns.begin);
        if (lit.end > columns.end) open(columns.end, lit.end);
        columns = {std::min(columns.begin, lit.begin), std::max(columns.end, lit.end)};
    }
    count_background(columns.begin, lit.begin);
    count_background(lit.end, columns.end);
    const float* const lr = s.r.data();
    const float* const lg = s.g.data();
    const float* const lb = s.b.data();
    if (!lit.background_between) {
        s.shaded_pixels += static_cast<std::size_t>(lit.end - lit.begin);
        const std::size_t count = static_cast<std::size_t>(lit.end - lit.begin);
        kernels.accumulate(lr + lit.begin, count, r + lit.begin);
        kernels.accumulate(lg + lit.begin, count, g + lit.begin);
        kernels.accumulate(lb + lit.begin, count, b + lit.begin);
        return;
    }
    const ShadeTriangle* const* const visible = s.visible.data() + offset;
    for (int x = lit.begin; x < lit.end; ++x) {
        if (!visible[x]) {
            ++background[x];
            continue;
        }
        ++s.shaded_pixels;
        r[x] += clamped(lr[x]);
        g[x] += clamped(lg[x]);
        b[x] += clamped(lb[x]);
    }
}

}  // namespace

void Pipeline::record_sample(const BandScratch& s, std::size_t offset, const LitRow& lit,
                             const SamplePass& pass) const {
    SampleProbe sample;
    sample.position = pass.position;
    const std::size_t x = static_cast<std::size_t>(probe_x);
    const ShadeTriangle* tri =
        probe_x >= lit.begin && probe_x < lit.end ? s.visible[offset + x] : nullptr;
    if (tri) {
        sample.hit = true;
        sample.object = tri->object;
        sample.light = {clamped(s.r[x]), clamped(s.g[x]), clamped(s.b[x])};
    } else {
        sample.light = {background_light[0], background_light[1], background_light[2]};
    }
    probed.samples.push_back(sample);
}

void Pipeline::draw_band_samples(int band, BandScratch& s, Image& image) const {
    const int width = image.width;
    const int row_begin = band * band_height;
    const int row_end = std::min(image.height, row_begin + band_height);
    const std::size_t pixels = static_cast<std::size_t>(band_height) * width;
    for (auto* v : {&s.sum_r, &s.sum_g, &s.sum_b}) v->resize(pixels);
    s.background_samples.resize(pixels);

    const std::span<const SamplePosition> pattern = sample_pattern(scene.output.samples);
    SampledColumns columns[band_height];
    for (SampledColumns& row : columns) row = {width, 0};
    for (std::size_t k = 0; k < pattern.size(); ++k) {
        const SamplePass pass(pattern[k]);
        rasterize_band(band, s, width, image.height, pass);
        for (int y = row_begin; y < row_end; ++y) {
            const std::size_t offset = static_cast<std::size_t>(y % band_height) * width;
            const LitRow lit = light_row(y, width, s, pass);
            if (y == probe_y) record_sample(s, offset, lit, pass);
            accumulate_row(kernels, s, offset, lit, static_cast<int>(k), columns[y % band_height]);
            clear_row(s, offset, lit.begin, lit.end);
        }
    }

    // The resolve: (1/N) · Σ L_k, a background sample's L_k being
    // background_light; then gamma and 8 bits by the encoder (whose clamp
    // changes nothing here). A pixel all of whose samples saw the
    // background is the background's colour exactly, as with one sample.
    const int count = static_cast<int>(pattern.size());
    const float inverse = 1.0f / static_cast<float>(count);  // exact: a power of two
    for (int y = row_begin; y < row_end; ++y) {
        std::uint8_t* const row = image.pixel(0, y);
        const auto [begin, end] = columns[y % band_height];
        auto fill_background = [&](int from, int to) {
            if (from < to)
                std::memcpy(row + 3 * from, background_row.data() + 3 * from,
                            3 * static_cast<std::size_t>(to - from));
        };
        fill_background(0, std::min(begin, width));
        fill_background(std::max(begin, end), width);
        if (begin >= end) continue;
        const std::size_t offset = static_cast<std::size_t>(y % band_height) * width;
        const std::uint8_t* const background = s.background_samples.data() + offset;
        float* const sums[3] = {s.sum_r.data() + offset, s.sum_g.data() + offset,
                                s.sum_b.data() + offset};
        for (int c = 0; c < 3; ++c) {
            const float light = background_light[c];
            for (int x = begin; x < end; ++x)
                sums[c][x] = (sums[c][x] + static_cast<float>(background[x]) * light) * inverse;
        }
        kernels.encode(sums[0] + begin, sums[1] + begin, sums[2] + begin,
                       static_cast<std::size_t>(end - begin), scene.output.gamma, row + 3 * begin);
        for (int x = begin; x < end; ++x)
            if (background[x] == count) fill_background(x, x + 1);
    }
}

}  // namespace litkit
