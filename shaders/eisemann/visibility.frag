#version 330 core
// Eisemann & Décoret, Occlusion Textures for Plausible Soft Shadows (2008).
// Per fragment P (in the light's frame: the light is the rectangle |x| ≤ light_half.x,
// |y| ≤ light_half.y on z = 0, the scene at z > 0):
//  - §3.1, equation 4: the light seen from P through a slice's plane at depth z_s is a
//    box of size s(P) = d(P, O)/d(P, S) · size(S) = (z_P − z_s)/z_P · size(S), centred
//    where the segment from P to the light's centre meets the plane: (x_P, y_P)·z_s/z_P;
//    the filtered occlusion there is the blocked fraction of the light (Figure 1).
//  - §3.2: the box filter read from the prefiltered occlusion textures: PREFILTER 0,
//    mipmaps — trilinear textureLod at level log2(box size in texels); PREFILTER 1,
//    N-buffers — level l = floor(log2 size) holds the box of 2^l texels anchored at its
//    lower-left texel, so the box centred at c is read at c − 2^l/2 (bilinearly), and
//    intermediate sizes interpolate levels l and l + 1 (Algorithm 1, lines 5–8);
//    PREFILTER 2, summed-area tables — the exact box, rectangular as the light's
//    projection is (see `sat_box`). Mipmaps and N-buffers take the square box of the
//    larger side.
//  - §3.3, equation 5: contributions combined by the probabilistic rule
//    V = Π_k (1 − I_k) (COMBINE 0); the sum (1) and the maximum (2) for comparison.
//  - §3.4.2 (self shadowing): the slice holding P is left out, and the slice above it
//    fades in linearly with P's distance below its lower plane, over one slice depth, so
//    that a surface never shadows itself through its own slice.
//  - The texture coordinates follow the slicing view of §3.4 / Figure 5 (slices.vert).
// The visibility is multiplied by the fraction of the light in front of P's plane
// (the truth's "facing" test, exact for the rectangle), P's plane the triangle's own
// (from the screen-space derivatives), turned towards the viewer.
// SUN 1 (§3.5, "sunlight"): the frame's z runs along the sun's light (the light is at
// z = −∞), the slicing view is orthographic, and from P the sun is a cone of half-angle θ:
// at a slice Δz closer to the sun it is the disc of radius R = Δz · tan θ around P's own
// (x, y), read as a Gaussian of deviation R/2 from the Gaussian pyramid in the occlusion
// textures' mipmap levels (gauss.frag: level l has deviation ≈ 0.645 · 2^l texels, so
// lod = log2(0.775 · R)). The facing term is the part of the sun's disc above P's plane.
// LOOK 1 (mask): the visibility as grey; LOOK 0 (shaded): light 0's diffuse term times
// the visibility, added over the fixed-function dim pass.

#if PREFILTER == 2
// Summed-area table k: S(i, j) = Σ occlusion over texels [0, i] × [0, j] (sat.frag).
uniform sampler2D sat0;
#if SLICES > 4
uniform sampler2D sat1;
#endif
#if SLICES > 8
uniform sampler2D sat2;
uniform sampler2D sat3;
#endif
#elif PREFILTER == 0
uniform sampler2D occlusion0;
#if SLICES > 4
uniform sampler2D occlusion1;
#endif
#if SLICES > 8
uniform sampler2D occlusion2;
uniform sampler2D occlusion3;
#endif
#else
// N-buffer levels of occlusion texture k: even levels stacked in even_k, odd in odd_k
// (level l at rows (l / 2) · texels), so that each level is made from the other texture.
uniform sampler2D even0;
uniform sampler2D odd0;
#if SLICES > 4
uniform sampler2D even1;
uniform sampler2D odd1;
#endif
#if SLICES > 8
uniform sampler2D even2;
uniform sampler2D odd2;
uniform sampler2D even3;
uniform sampler2D odd3;
#endif
#endif

uniform float cop;          // the centre of projection's distance behind the light
uniform vec2 half_window;   // the slicing window's half extents on the light's plane
uniform vec2 light_half;    // the light's half extents
uniform float slice_near;   // depth of the first slice's top plane
uniform float slice_depth;  // Δ
uniform float texels;       // occlusion texture edge, in texels
uniform float receives;     // 1: the object takes shadows; 0: only the facing term
uniform vec4 camera_light;  // the camera's position in the light's frame (w = 1)
#if SUN
uniform float sun_tan;      // tan θ: the sun's disc radius per unit of distance
#endif
#if LOOK == 0
uniform vec4 ff_light0_position;
uniform vec4 ff_light0_diffuse;
uniform vec4 ff_front_diffuse;
#endif

in vec3 light_frame;
in vec3 eye_position;
in vec3 eye_normal;
out vec4 colour;

#if PREFILTER == 1
// N-buffer level l of texture t (all four slices) for the box of 2^l texels centred at uv.
vec4 nbuffer(int t, int l, vec2 uv) {
    float box = exp2(float(l));
    vec2 corner = clamp(uv * texels - 0.5 * box + 0.5, vec2(0.5), vec2(texels - 0.5));
    float rows = float((LEVELS + 1) / 2) * texels;
    vec2 st = vec2(corner.x / texels, (float(l / 2) * texels + corner.y) / rows);
    bool odd = (l - 2 * (l / 2)) == 1;
    if (t == 0) {
        return odd ? textureLod(odd0, st, 0.0) : textureLod(even0, st, 0.0);
    }
#if SLICES > 4
    if (t == 1) {
        return odd ? textureLod(odd1, st, 0.0) : textureLod(even1, st, 0.0);
    }
#endif
#if SLICES > 8
    if (t == 2) {
        return odd ? textureLod(odd2, st, 0.0) : textureLod(even2, st, 0.0);
    }
    return odd ? textureLod(odd3, st, 0.0) : textureLod(even3, st, 0.0);
#else
    return vec4(0.0);
#endif
}

float slice_occlusion(int j, vec2 uv, vec2 box) {
    float size = max(box.x, box.y);
    int t = j / 4;
    int c = j - 4 * t;
    float level = clamp(log2(max(size, 1.0)), 0.0, float(LEVELS - 1));
    int l = int(floor(level));
    float f = level - float(l);
    vec4 lo = nbuffer(t, l, uv);
    vec4 o = f > 0.0 ? mix(lo, nbuffer(t, min(l + 1, LEVELS - 1), uv), f) : lo;
    return c == 0 ? o.r : c == 1 ? o.g : c == 2 ? o.b : o.a;
}
#elif PREFILTER == 2
// The integral of texture t's occlusion over [0, x] (texels, x in [0, texels]²). On each
// texel cell it is bilinear (a + b·x + c·y + d·x·y: the sum of the whole texels below and
// left plus the texel's value times the covered area), so interpolating S between cell
// corners is exact: S(i, j) is the integral up to the corner (i + 1, j + 1), read at
// texel position (i + 1) − ½ by LINEAR filtering, and the 0 border gives the integral up
// to the edge 0. The rounding: the interpolation weights times sums of up to texels²,
// about 2^-24 · texels² per corner, i.e. 0.016 of a texel at 512² — 1.6% of a one-texel
// box, 0.1% of a 4 × 4 one.
vec4 sat_integral(int t, vec2 x) {
    vec2 st = (clamp(x, vec2(0.0), vec2(texels)) - 0.5) / texels;
    if (t == 0) {
        return textureLod(sat0, st, 0.0);
    }
#if SLICES > 4
    if (t == 1) {
        return textureLod(sat1, st, 0.0);
    }
#endif
#if SLICES > 8
    if (t == 2) {
        return textureLod(sat2, st, 0.0);
    }
    return textureLod(sat3, st, 0.0);
#else
    return vec4(0.0);
#endif
}

// The exact mean occlusion over the box of box.x × box.y texels (at least one texel)
// centred at uv (Crow 1984): S(x1, y1) − S(x0, y1) − S(x1, y0) + S(x0, y0) over the box's
// area. The part of the box beyond the window reads no occluder (the clamp above), as the
// other prefilters' 0 border.
float slice_occlusion(int j, vec2 uv, vec2 box) {
    int t = j / 4;
    vec2 half_box = 0.5 * max(box, vec2(1.0));
    vec2 lo = uv * texels - half_box;
    vec2 hi = uv * texels + half_box;
    vec4 sum = sat_integral(t, hi) - sat_integral(t, vec2(lo.x, hi.y))
               - sat_integral(t, vec2(hi.x, lo.y)) + sat_integral(t, lo);
    vec4 o = clamp(sum / (4.0 * half_box.x * half_box.y), 0.0, 1.0);
    int c = j - 4 * t;
    return c == 0 ? o.r : c == 1 ? o.g : c == 2 ? o.b : o.a;
}
#else
// The filtered occlusion of slice j around uv with a box of the larger side of `box`.
float slice_occlusion(int j, vec2 uv, vec2 box) {
    float size = max(box.x, box.y);
    float lod = log2(max(size, 1.0));
    int t = j / 4;
    vec4 o;
    if (t == 0) {
        o = textureLod(occlusion0, uv, lod);
    }
#if SLICES > 4
    else if (t == 1) {
        o = textureLod(occlusion1, uv, lod);
    }
#endif
#if SLICES > 8
    else if (t == 2) {
        o = textureLod(occlusion2, uv, lod);
    } else {
        o = textureLod(occlusion3, uv, lod);
    }
#endif
    int c = j - 4 * t;
    return c == 0 ? o.r : c == 1 ? o.g : c == 2 ? o.b : o.a;
}
#endif

#if !SUN
// The fraction of the light rectangle where n · (q − p) > 0: the rectangle clipped by the
// plane (Sutherland–Hodgman against f(x, y) = n.x·x + n.y·y − n·p), its area by the
// shoelace formula, over the rectangle's.
float facing_fraction(vec3 p, vec3 n) {
    vec2 corner[4] = vec2[4](vec2(-light_half.x, -light_half.y), vec2(light_half.x, -light_half.y),
                             vec2(light_half.x, light_half.y), vec2(-light_half.x, light_half.y));
    float d = dot(n, p);
    vec2 kept[6];
    int count = 0;
    for (int i = 0; i < 4; ++i) {
        vec2 a = corner[i];
        vec2 b = corner[(i + 1) % 4];
        float fa = dot(n.xy, a) - d;
        float fb = dot(n.xy, b) - d;
        if (fa > 0.0) {
            kept[count++] = a;
        }
        if ((fa > 0.0) != (fb > 0.0)) {
            kept[count++] = mix(a, b, fa / (fa - fb));
        }
    }
    float area = 0.0;
    for (int i = 0; i < count; ++i) {
        vec2 a = kept[i];
        vec2 b = kept[(i + 1) % count];
        area += a.x * b.y - b.x * a.y;
    }
    return clamp(0.5 * abs(area) / (4.0 * light_half.x * light_half.y), 0.0, 1.0);
}
#endif

#if SUN
// The fraction of the sun's disc where n · ω > 0. In the plane across the cone's axis
// w = (0, 0, −1) the disc has radius tan θ and the plane n cuts it along a line at signed
// distance h = (n · w) / (|n − (n · w) w| · tan θ) disc radii from the centre; the part on
// the centre's side is 1 − (acos h − h √(1 − h²)) / π (the circular segment's area).
float facing_fraction(vec3 p, vec3 n) {
    float along = -n.z;
    float across = length(n.xy);
    if (across <= 1e-6) {
        return along > 0.0 ? 1.0 : 0.0;
    }
    float h = clamp(along / (across * sun_tan), -1.0, 1.0);
    return clamp(1.0 - (acos(h) - h * sqrt(1.0 - h * h)) / 3.14159265, 0.0, 1.0);
}
#endif

float visibility(vec3 p) {
    float product = 1.0;  // equation 5
    float sum = 0.0;
    float maximum = 0.0;
    for (int j = 0; j < SLICES; ++j) {
        float z_top = slice_near + float(j) * slice_depth;
        float weight = clamp((p.z - (z_top + slice_depth)) / slice_depth, 0.0, 1.0);
#if SUN
        if (weight <= 0.0) {
            break; // this slice and the ones below it are not between P and the sun
        }
        float z_s = z_top + 0.5 * slice_depth;
        vec2 uv = 0.5 + 0.5 * p.xy / half_window;   // the rays towards the sun are parallel
        float radius = (p.z - z_s) * sun_tan * texels / (2.0 * half_window.x); // R, texels
        vec2 box = vec2(0.775 * radius);            // lod = log2(0.775 R), see the header
#else
        if (weight <= 0.0 || p.z <= 0.0) {
            break; // this slice and the ones below it are not between P and the light
        }
        float z_s = z_top + 0.5 * slice_depth;      // the slice's plane: its middle
        float t = (p.z - z_s) / p.z;                // d(P, O) / d(P, S), equation 4
        vec2 centre = p.xy * (z_s / p.z);           // on the segment from P to the centre
        vec2 to_texture = cop / ((z_s + cop) * half_window); // plane → [−1, 1] of the window
        vec2 uv = 0.5 + 0.5 * centre * to_texture;
        vec2 box = light_half * t * to_texture * texels;     // box size in texels
#endif
        float occluded = weight * slice_occlusion(j, uv, box);
        product *= 1.0 - occluded;
        sum += occluded;
        maximum = max(maximum, occluded);
    }
#if COMBINE == 0
    return product;
#elif COMBINE == 1
    return 1.0 - min(sum, 1.0);
#else
    return 1.0 - maximum;
#endif
}

void main() {
    vec3 n = normalize(cross(dFdx(light_frame), dFdy(light_frame)));
    if (dot(n, camera_light.xyz - light_frame) < 0.0) {
        n = -n; // the side the viewer sees
    }
    float v = facing_fraction(light_frame, n);
    if (receives > 0.5 && v > 0.0) {
        v *= visibility(light_frame);
    }
#if LOOK == 1
    colour = vec4(v, v, v, 1.0);
#else
    vec3 l = normalize(ff_light0_position.xyz - eye_position * ff_light0_position.w);
    float diffuse = max(dot(normalize(eye_normal), l), 0.0);
    if (!gl_FrontFacing) {
        diffuse = max(dot(-normalize(eye_normal), l), 0.0);
    }
    colour = vec4(v * diffuse * ff_light0_diffuse.rgb * ff_front_diffuse.rgb, 1.0);
#endif
}
