#version 330 core
// Eisemann & Décoret 2008, §3.2: N-buffers used "to compute the mean of neighboring
// pixels. Each texel, of a level l, holds the normalized response of a box filter with a
// kernel size of 2^l × 2^l", built dyadically "using four lookups per level":
//   N_l(i, j) = ¼ [N_{l−1}(i, j) + N_{l−1}(i + h, j) + N_{l−1}(i, j + h) + N_{l−1}(i + h, j + h)],
// h = 2^(l−1), so N_l(i, j) is the mean of texels [i, i + 2^l) × [j, j + 2^l); texels
// beyond the texture are 0 (no occluder outside the slicing window). Levels are stacked
// in the rows of a texture, level l−1 read from `source` at row `source_row`, level l
// written at row `target_row` of the framebuffer's texture.
uniform sampler2D source;
uniform int source_row;
uniform int target_row;
uniform int half_box;   // h = 2^(l−1)
uniform int texels;     // the occlusion texture's edge

out vec4 mean;

vec4 fetch(ivec2 q) {
    if (q.x >= texels || q.y >= texels) {
        return vec4(0.0);
    }
    return texelFetch(source, q + ivec2(0, source_row), 0);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) - ivec2(0, target_row);
    mean = 0.25 * (fetch(p) + fetch(p + ivec2(half_box, 0)) + fetch(p + ivec2(0, half_box))
                   + fetch(p + ivec2(half_box)));
}
