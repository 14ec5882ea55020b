#version 330 core
// Coleman, "Fast Self-Shadowing Using Occluder Textures" (M.S. thesis, Texas A&M, 2006),
// Appendix A, "Example Vertex Shader Source": the F-35's shadowing coordinates for three
// shadow planes, ported from Cg to GLSL 3.30. Line numbers are those of the thesis's
// plain-text edition (Appendix A starts at line 499); 541-543, 586-588, 631-633 and
// 675-677 are page breaks inside the listing.
//
//   504-514  struct appin                    -> struct appin + four attributes
//   516-529  struct vertout                  -> the `out vertout { ... } OUT` block
//   531-536  f35ShadowVertexShader, OUT      -> the same function, void (OUT is the block),
//                                               called by main()
//   538-555  glstate matrices, light, material -> uniforms u_*, copied to the Cg names
//   557-565  directional lighting, ambient   -> unchanged, plus the COLOR0 clamp (below)
//   567-569  clip-space position             -> gl_Position
//   571-573  base texture coordinate         -> unchanged
//   575-607  z = 0 plane, texcoord1          -> unchanged
//   609-648  right tail fin plane, texcoord2 -> unchanged
//   650-687  left tail fin plane, texcoord3  -> unchanged
//   689-690  return OUT                      -> dropped: OUT is the output block
//
// What changed, and why:
// - Types: float2/3/4 -> vec2/3/4, float4x4 -> mat4, float3x3 -> mat3, `float3(...)` ->
//   `vec3(...)`. The cast `(float3x3)(M)` keeps the upper-left 3x3, as `mat3(M)` does.
// - `mul(M, v)` -> `M * v`. The rule: Cg's glstate matrices are bound so that `mul(M, v)`
//   treats v as a column vector and computes what GL computes; the uniforms here take GL's
//   own column-major arrays (glGetFloatv(GL_MODELVIEW_MATRIX), glam's `to_cols_array`)
//   with transpose = GL_FALSE, and GLSL's `M * v` is then the same product. The appendix
//   has no `mul(v, M)`.
// - glstate has no GLSL 3.30 core counterpart (the gl_ModelViewMatrix family exists only in
//   the compatibility profile), so each member becomes a uniform the application sets:
//     glstate.matrix.mvp                   -> u_modelview_projection
//     glstate.matrix.modelview[0]          -> u_modelview
//     glstate.matrix.inverse.modelview[0]  -> u_modelview_inverse
//     glstate.matrix.invtrans.modelview[0] -> u_modelview_inverse_transpose
//     glstate.light[0].position            -> u_light_position (eye space, as GL keeps it)
//     glstate.light[0].diffuse / .ambient  -> u_light_diffuse / u_light_ambient
//     glstate.material.ambient / .diffuse  -> u_material_ambient / u_material_diffuse
//   The Cg locals keep their names (modelViewProj, ..., materialDiffuse) but lose `const`:
//   in GLSL 3.30 a const initializer must be a constant expression, and a uniform is not.
//   `modelView` is unused, in the Cg as here; the compiler drops u_modelview.
// - Semantics: vertex inputs cannot be structs in GLSL, so each appin member arrives as an
//   attribute at an explicit location, in appin's order (POSITION 0, NORMAL 1, COLOR0 2,
//   TEXCOORD0 3), and main() assembles `appin IN` from them before calling the function.
//   The vertout members become an output interface block named vertout (matched by name
//   in the fragment shader); POSITION becomes gl_Position, which cannot be a block member.
//   TEXCOORDn and smooth `out` both interpolate perspective-correctly in full float.
// - COLOR0: GL clamps a vertex colour to [0, 1] before rasterisation (GL 2.0 §2.14.6,
//   Clamping or Masking, which also holds for a vertex program's result.color, the
//   register Cg's GL vertex profiles write COLOR0 to); a generic GLSL output is not
//   clamped, so one line after the Cg assignment does it. Nothing else is added.
// - Kept as written, including what a modern port would fix: lightDirection_eye is the
//   light's position with w ignored (a directional light is assumed) and is not normalized
//   before the diffuse dot product; the tail planes divide by dot(N, L), which is 0 when the
//   light is parallel to a plane; texcoord2.w and texcoord3.w are never written.
// - The comment at line 653 gives the left fin's V0 as (0.899235, ...); the code at 659,
//   kept here, uses -0.899235, the mirror of the right fin's origin.

struct appin
{
    vec4 position;
    vec3 normal;
    vec4 color0;
    vec4 texcoord0;
};

layout(location = 0) in vec4 a_position;  // POSITION
layout(location = 1) in vec3 a_normal;    // NORMAL
layout(location = 2) in vec4 a_color0;    // COLOR0
layout(location = 3) in vec4 a_texcoord0; // TEXCOORD0

//-----
// vertout - the per-vertex attributes to be passed to the
//           fragment shader, interpolated across the triangle
//-----
out vertout
{
    vec4 color0;    // COLOR0
    vec4 texcoord0; // TEXCOORD0
    vec4 texcoord1; // TEXCOORD1
    vec4 texcoord2; // TEXCOORD2
    vec4 texcoord3; // TEXCOORD3
    vec4 ambient;   // TEXCOORD4
} OUT;

uniform mat4 u_modelview_projection;        // glstate.matrix.mvp
uniform mat4 u_modelview;                   // glstate.matrix.modelview[0]
uniform mat4 u_modelview_inverse;           // glstate.matrix.inverse.modelview[0]
uniform mat4 u_modelview_inverse_transpose; // glstate.matrix.invtrans.modelview[0]
uniform vec4 u_light_position;              // glstate.light[0].position
uniform vec4 u_light_diffuse;               // glstate.light[0].diffuse
uniform vec4 u_light_ambient;               // glstate.light[0].ambient
uniform vec4 u_material_ambient;            // glstate.material.ambient
uniform vec4 u_material_diffuse;            // glstate.material.diffuse

//-----
// f35ShadowVertexShader - the main program
//-----
void f35ShadowVertexShader( appin IN )
{
    // glstate is a pre-defined Cg parameter that queries the OpenGL state
    // machine directly. For a full set of available parameters, see the
    // Cg Toolkit User's Manual from NVidia.

    mat4 modelViewProj = u_modelview_projection;
    mat4 modelView = u_modelview;
    mat4 modelViewInv = u_modelview_inverse;
    mat4 modelViewIT = u_modelview_inverse_transpose;
    vec4 lightDirection_eye = u_light_position;
    vec4 lightDiffuse = u_light_diffuse;
    vec4 lightAmbient = u_light_ambient;
    vec4 materialAmbient = u_material_ambient;
    vec4 materialDiffuse = u_material_diffuse;

    // compute directional lighting in eye-space

    vec3 N_eye = normalize( mat3(modelViewIT) * IN.normal );
    float cos_ang = max(dot(N_eye, lightDirection_eye.xyz), 0.0);
    vec3 diffuse = cos_ang * materialDiffuse.rgb * lightDiffuse.rgb;
    // pass the directional color and ambient color to the fragment shader

    OUT.color0 = vec4(IN.color0.rgb * diffuse, IN.color0.a);
    OUT.color0 = clamp(OUT.color0, 0.0, 1.0); // the COLOR0 semantic's clamp
    OUT.ambient = lightAmbient * materialAmbient;

    // transform the vertex for clipping

    gl_Position = modelViewProj * IN.position;

    // pass texture coordinates for the base texture

    OUT.texcoord0 = IN.texcoord0;

    // compute shadow coordinates for the first shadow map

    // compute the intersection of a line with the z=0 plane
    // the line begins at vertex point and travels along lightDirection
    // computed in model-space

    vec3 lightDirection_model =
        normalize( mat3(modelViewInv) * lightDirection_eye.xyz );

    // find the intersection point in model-space

    // remember that for the z=0 plane, sI = -pos.z/light.z

    vec2 intersection = IN.position.xy +
        (-IN.position.z/lightDirection_model.z)*lightDirection_model.xy;

    // convert to a texture coordinate using
    // V0 = (-7.5, -5.315, 0.0)
    // N = (0, 0, 1)
    // and size of shadow plane = 15.0m on each side

    vec2 normalizedTexCoord = (intersection + vec2(7.5, 5.315)) / 15.0;

    // the z coordinate is used to determine if this part of the aircraft is
    // closer to the light source than the shadow plane (and should not be
    // shadowed), or behind the shadow plane, and should be shadowed.

    float zTexCoord = lightDirection_model.z*IN.position.z;
    OUT.texcoord1 = vec4(normalizedTexCoord, zTexCoord, 1.0);

    // compute shadow coordinates for the right tail fin shadow map

    // intersection of a line with the shadow plane
    // V0 = (0.899235, -0.676381, -0.706742)
    // N = (-0.917594, 0.0, 0.397518)
    // line begins at vertex point P0 and travels along lightDirection
    // computed in model-space

    vec3 N = vec3(-0.917594, 0.0, 0.397518);
    vec3 V0 = vec3(0.899235, -0.676381, -0.706742);
    vec3 V0minusP0 = V0 - IN.position.xyz;
    float numerator = dot(N, V0minusP0);
    float denominator = dot(N, lightDirection_model);
    float sI = numerator / denominator;

    // find the intersection point in model-space

    vec3 intersectionVec = lightDirection_model.xyz * sI;
    vec3 intersectionRTail = IN.position.xyz + intersectionVec;

    // convert to a texture coordinate

    // size of shadow plane = 4.1218186m on each side
    // the normalized up vector for this tail fin's shadow plane
    // is = (0.3975177, 0.0, 0.91759448)

    vec3 distanceVec = intersectionRTail - V0;
    vec3 upVec = vec3(0.3975177, 0.0, 0.91759448);
    OUT.texcoord2.x = - distanceVec.y / 4.1218186;
    OUT.texcoord2.y = dot( distanceVec, upVec ) / 4.1218186;

    // the z coordinate is used to determine if this part of the aircraft is
    // closer to the light source than the shadow plane (and should not be
    // shadowed), or behind the shadow plane, and should be shadowed.

    OUT.texcoord2.z = dot(-intersectionVec, lightDirection_model);

    // compute shadow coordinates for the left tail fin shadow map

    // intersection of a line with the shadow plane
    // V0 = (0.899235, -0.676381, -0.706742)
    // N = (0.917594, 0.0, 0.397518)
    // line begins at vertex point P0 and travels along lightDirection
    // computed in model-space

    N = vec3(0.917594, 0.0, 0.397518);
    V0 = vec3(-0.899235, -0.676381, -0.706742);
    V0minusP0 = V0 - IN.position.xyz;
    numerator = dot(N, V0minusP0);
    denominator = dot(N, lightDirection_model);
    sI = numerator / denominator;

    // find the intersection point in model-space

    intersectionVec = lightDirection_model.xyz * sI;
    vec3 intersectionLTail = IN.position.xyz + intersectionVec;

    // convert to a texture coordinate
    // size of shadow plane = 4.1218186m on each side
    // the normalized up vector for this tail fin's shadow plane
    // is = (-0.3975177, 0.0, 0.91759448)

    distanceVec = intersectionLTail - V0;
    upVec = vec3(-0.3975177, 0.0, 0.91759448);
    OUT.texcoord3.x = - distanceVec.y / 4.1218186;
    OUT.texcoord3.y = dot( distanceVec, upVec ) / 4.1218186;

    // the z coordinate is used to determine if this part of the aircraft is
    // closer to the light source than the shadow plane (and should not be
    // shadowed), or behind the shadow plane, and should be shadowed.

    OUT.texcoord3.z = dot(-intersectionVec, lightDirection_model);
}

void main()
{
    f35ShadowVertexShader( appin(a_position, a_normal, a_color0, a_texcoord0) );
}
