#version 330 core
// Eisemann & Décoret 2008, §3.4: the scene cut into SLICES uniform slices parallel to the
// light, each slice's binary occlusion (1 where an occluder is, the paper's 1 − δ of
// equation 3 inverted) kept in one colour channel, four slices to an RGBA texture
// ("each slice is represented by one color channel"). One pass per texture: this fragment
// writes 1 into the channel of its slice when that channel belongs to the texture drawn
// (`first_slice` is the slice in red); additive blending ONE, ONE saturates at 1, the
// union of the slice's occluders.
// §3.4.1 (light leaks, Figure 6): with LEAK_FIX each slice is also projected onto its
// successor further from the light — the fragment fills two channels.
uniform float slice_near;   // depth of the first slice's top plane
uniform float slice_depth;  // Δ, the depth of one slice
uniform float first_slice;  // the slice held in this texture's red channel

in float depth;
out vec4 occlusion;

void main() {
    if (depth < slice_near) {
        discard; // between the light and the first slice: nothing is there to slice
    }
    float slice = min(floor((depth - slice_near) / slice_depth), float(SLICES - 1));
    vec4 channel = vec4(first_slice) + vec4(0.0, 1.0, 2.0, 3.0);
    vec4 here = vec4(equal(channel, vec4(slice)));
#if LEAK_FIX
    here = max(here, vec4(equal(channel, vec4(slice + 1.0))));
#endif
    occlusion = here;
}
