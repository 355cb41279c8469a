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

// One sample of a row into the band's sums at `offset`: the lit columns'
// clamped light, and a count of background samples for the others. The
// first sample sets the sums, the others add to them.
void accumulate_row(BandScratch& s, std::size_t offset, const LitRow& lit, int width, bool first) {
    float* const r = s.sum_r.data() + offset;
    float* const g = s.sum_g.data() + offset;
    float* const b = s.sum_b.data() + offset;
    std::uint8_t* const background = s.background_samples.data() + offset;
    const ShadeTriangle* const* const visible = s.visible.data() + offset;
    if (first) {
        std::fill_n(r, width, 0.0f);
        std::fill_n(g, width, 0.0f);
        std::fill_n(b, width, 0.0f);
        std::fill_n(background, width, std::uint8_t{0});
    }
    for (int x = 0; x < lit.begin; ++x) ++background[x];
    for (int x = std::max(lit.begin, lit.end); x < width; ++x) ++background[x];
    for (int x = lit.begin; x < lit.end; ++x) {
        if (lit.background_between && !visible[x]) {
            ++background[x];
            continue;
        }
        ++s.shaded_pixels;
        r[x] += clamped(s.r[static_cast<std::size_t>(x)]);
        g[x] += clamped(s.g[static_cast<std::size_t>(x)]);
        b[x] += clamped(s.b[static_cast<std::size_t>(x)]);
    }
}

}  // namespace

void Pipeline::draw_band_samples(int band, BandScratch& s, Image& image) const {
    const int width = image.width;
    const int row_begin = band * band_height;
    const int row_end = std::min(image.height, row_begin + band_height);
    const std::size_t pixels = static_cast<std::size_t>(band_height) * width;
    for (auto* v : {&s.sum_r, &s.sum_g, &s.sum_b}) v->resize(pixels);
    s.background_samples.resize(pixels);

    const std::span<const SamplePosition> pattern = sample_pattern(scene.output.samples);
    for (std::size_t k = 0; k < pattern.size(); ++k) {
        const SamplePass pass(pattern[k]);
        rasterize_band(band, s, width, image.height, pass);
        for (int y = row_begin; y < row_end; ++y) {
            const std::size_t offset = static_cast<std::size_t>(y % band_height) * width;
            const LitRow lit = light_row(y, width, s, pass);
            accumulate_row(s, offset, lit, width, k == 0);
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
        const std::size_t offset = static_cast<std::size_t>(y % band_height) * width;
        const std::uint8_t* const background = s.background_samples.data() + offset;
        float* const sums[3] = {s.sum_r.data() + offset, s.sum_g.data() + offset,
                                s.sum_b.data() + offset};
        for (int c = 0; c < 3; ++c) {
            const float light = background_light[c];
            for (int x = 0; x < width; ++x)
                sums[c][x] = (sums[c][x] + static_cast<float>(background[x]) * light) * inverse;
        }
        std::uint8_t* const row = image.pixel(0, y);
        kernels.encode(sums[0], sums[1], sums[2], static_cast<std::size_t>(width),
                       scene.output.gamma, row);
        for (int x = 0; x < width; ++x)
            if (background[x] == count) std::memcpy(row + 3 * x, background_row.data() + 3 * x, 3);
    }
}

}  // namespace litkit
