#version 330 core
// Coleman, "Fast Self-Shadowing Using Occluder Textures" (M.S. thesis, Texas A&M, 2006),
// Appendix B, "Example Fragment Shader Source": the occluder-texture look-ups, the sign
// test and the final colour, ported from Cg to GLSL 3.30. Line numbers are those of the
// thesis's plain-text edition (Appendix B starts at line 694); 736-738 is a page break
// inside the listing.
//
//   699-712  struct vertout                  -> the `in vertout { ... } IN` block
//   714-720  struct pixout                   -> struct pixout + one output at location 0
//   722-730  f35ShadowFragmentShader( vertout IN, three samplers ) -> the same function
//            without parameters (IN is the block, the samplers are uniforms of the same
//            names), called by main()
//   732-734  base texture look-up            -> unchanged but for tex2D
//   739-748  three occluder look-ups, saturate -> texture(), clamp(), `.x`
//   750-752  diffuse colour                  -> unchanged
//   754-760  sign tests, product of shadows  -> unchanged
//   762-768  lit colour + ambient            -> `IN.ambient.rgb`
//   770-771  return OUT                      -> unchanged; main() writes OUT.color
//
// What changed, and why:
// - Types: float3/float4 -> vec3/vec4.
// - `tex2D(s, c)` -> `texture(s, c)`; `saturate(x)` -> `clamp(x, 0.0, 1.0)`.
// - Cg truncates a vector to a smaller type implicitly, GLSL does not; the two places it
//   does so are written out: `float shadowColor = tex2D(...)` keeps the first component (`.x`;
//   a GL_LUMINANCE occluder returns (L, L, L, 1), a GL_R8 one (r, 0, 0, 1): .x is the
//   occluder either way), and `texColor.rgb * IN.ambient` multiplies by `IN.ambient.rgb`.
// - Semantics: the vertout members arrive as an input interface block named vertout,
//   matched by name with the vertex shader's output block. Its POSITION member (which a Cg
//   fragment profile reads as the window position; the code never reads it) is dropped. The sampler parameters
//   `uniform sampler2D colorTEX : TEXUNIT0` (and shadowTEX : TEXUNIT1, shadowTEX2 :
//   TEXUNIT2) become uniforms of the same names; GLSL 3.30 has no layout(binding), so the
//   application sets them to units 0, 1 and 2 with glUniform1i. pixout's COLOR becomes
//   `layout(location = 0) out vec4 frag_color`, written by main() from the returned OUT.
// - Kept as written: the look-ups are clamped by saturate rather than by the texture's wrap
//   mode (lines 742-744 explain why); under GL_REPEAT, a coordinate clamped to exactly 1.0
//   wraps to the first texel. A plane's occluder counts only where texcoordN.z < 0 (the
//   plane lies between the point and the light); z == 0, a point on the plane, is lit.

//-----
// vertout - the per-vertex attributes to be passed to the
//           fragment shader, interpolated across the triangle
//-----
in vertout
{
    vec4 color0;    // COLOR0
    vec4 texcoord0; // TEXCOORD0
    vec4 texcoord1; // TEXCOORD1
    vec4 texcoord2; // TEXCOORD2
    vec4 texcoord3; // TEXCOORD3
    vec4 ambient;   // TEXCOORD4
} IN;

//-----
// pixout - the output of the fragment shader
//-----
struct pixout
{
    vec4 color;
};

layout(location = 0) out vec4 frag_color; // COLOR

uniform sampler2D colorTEX;   // TEXUNIT0
uniform sampler2D shadowTEX;  // TEXUNIT1
uniform sampler2D shadowTEX2; // TEXUNIT2

//-----
// f35ShadowFragmentShader - the main program
//-----
pixout f35ShadowFragmentShader()
{
    pixout OUT;

    // lookup the base texture color

    vec4 texColor = texture( colorTEX, IN.texcoord0.xy );

    // perform the shadow plane lookups
    // this model has 3 shadow planes

    // the texcoords for shadow lookup need to be clamped [0,1]
    // setting the texture wrap to clamp would work but shows a strange
    // performance problem on the latest nVidia drivers.

    float shadowColor = texture( shadowTEX, clamp(IN.texcoord1.xy, 0.0, 1.0) ).x;
    float shadowColor2 = texture( shadowTEX2, clamp(IN.texcoord2.xy, 0.0, 1.0) ).x;
    float shadowColor3 = texture( shadowTEX2, clamp(IN.texcoord3.xy, 0.0, 1.0) ).x;

    // apply the diffuse lighting

    vec4 diffuseColor = IN.color0 * texColor;

    // test whether this fragment is in front of or behind the shadow map

    float shadowPercent = (IN.texcoord1.z < 0.0) ? shadowColor : 1.0;
    float shadowPercent2 = (IN.texcoord2.z < 0.0) ? shadowColor2 : 1.0;
    float shadowPercent3 = (IN.texcoord3.z < 0.0) ? shadowColor3 : 1.0;
    shadowPercent *= shadowPercent2;
    shadowPercent *= shadowPercent3;

    // this final fragment color is the diffuse lighting with shadowing
    // plus the ambient lighting contribution

    vec3 outcolor = diffuseColor.rgb * shadowPercent
                  + texColor.rgb * IN.ambient.rgb;

    OUT.color = vec4(outcolor, diffuseColor.a);

    return OUT;
}

void main()
{
    frag_color = f35ShadowFragmentShader().color;
}
