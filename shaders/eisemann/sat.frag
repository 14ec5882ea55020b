#version 330 core
// Eisemann & Décoret 2008, §3.2: "Summed Area Tables (SAT) [Cro84] allow to compute the
// exact filter response for a rectangular kernel ... To avoid precision artifacts 32 bit
// textures are required." Built on the GPU as in [HSC*05] (Hensley et al. 2005), by
// recursive doubling: one pass per power of two, rows first, then columns,
//   S_{i+1}(p) = S_i(p) + S_i(p − offset_i),  offset_i = (2^i, 0) or (0, 2^i),
// S_i = 0 before the first texel, S_0 = the occlusion texture. After ⌈log2 n⌉ passes along
// x and as many along y, S(i, j) = Σ_{i' ≤ i, j' ≤ j} occlusion(i', j') for each of the
// four slices of an RGBA texture, in 32-bit floats (binary texels: sums are integers, exact
// up to 2^24, so tables up to 4096² are exact).
uniform sampler2D source;
uniform int offset_x;
uniform int offset_y;

out vec4 sum;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 q = p - ivec2(offset_x, offset_y);
    sum = texelFetch(source, p, 0);
    if (q.x >= 0 && q.y >= 0) {
        sum += texelFetch(source, q, 0);
    }
}
