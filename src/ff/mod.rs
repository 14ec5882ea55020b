//! The `ff` layer: the OpenGL 1.x fixed-function pipeline as data and rules, with no GL calls.
//!
//! - [`Command`] lists every GL-like operation once, as data. Techniques emit commands, the
//!   pipelines (`emulate`, `native`) execute them, [`script`] reads and prints them as the C
//!   calls of the era.
//! - [`FixedState`] is the GL 1.x state with every initial value documented;
//!   [`FixedState::apply`] folds a command in with GL's error semantics (an error leaves the
//!   state unchanged; the first error sticks until read).
//! - The small modules hold the GL rules both pipelines and the tests need, each with its
//!   formula: matrices ([`matrix`]), texgen ([`texgen`]), texture environments ([`texenv`]),
//!   register combiners ([`combiners`]), fog ([`fog`]), per-fragment tests ([`fragment`]).
//! - [`query`] answers every glGet, glIsEnabled and per-object getter from the state, with
//!   GL's (and Mesa's) type conversions; [`attrib`] is the glPushAttrib/glPopAttrib stack.
//!
//! Eye planes and light positions are transformed by the modelview current when they are
//! set (GL 1.5 §2.11.4, §2.14.1), never at draw time. Depth readback conversions belong to
//! the `gpu` layer.

pub mod accum;
pub mod api;
pub mod apply;
mod apply_compressed;
mod apply_framebuffer;
pub mod args;
pub mod attrib;
pub mod blit;
pub mod buffers;
pub mod calls;
pub mod calls_attrib;
pub mod calls_compressed;
pub mod calls_framebuffer;
pub mod calls_pixels;
pub mod calls_raster;
pub mod client;
pub mod color_index;
pub mod combiner_model;
pub mod combiners;
pub mod command;
pub mod compressed;
pub mod error;
pub mod float_token;
pub mod fog;
pub mod fragment;
pub mod framebuffer;
pub mod front;
pub mod geometry;
pub mod glenum;
pub mod immediate;
pub mod index_pixels;
pub mod light;
pub mod list_pairs;
pub mod lists;
pub mod matrix;
pub mod matrix_ops;
pub mod pixels;
pub mod point;
pub mod precision;
pub mod program;
pub mod queries;
pub mod query;
pub mod raster;
pub mod raster_light;
mod repeated_draws;
pub mod sample_coverage;
pub mod script;
pub mod state;
pub mod stipple;
pub mod texenv;
pub mod texgen;
pub mod texture;
// Client pixel storage and attribute stack, the queries' answers, GL 1.0–1.5 variants.
pub mod answer;
pub mod calls_variants;
pub mod client_attrib;
pub mod front_state;
pub mod pixel_layout;
pub mod pixel_map;
pub mod pixel_store;
pub mod pixel_types;
mod texture_border;
pub mod texture_calls;
pub mod texture_storage;
pub mod texture_volume;
pub mod upload_bounds;

#[cfg(test)]
mod state_tests;

pub use attrib::{AttribFrame, AttribGroup, AttribMask, MAX_ATTRIB_STACK_DEPTH};
pub use combiners::{
    CombinerBias, CombinerInput, CombinerOutput, CombinerParam, CombinerScale, ComponentUsage,
    FinalVariable, GeneralStage, Mapping, Portion, Product, Register, RegisterCombiners,
    StagePortion, SumOrMux, Variable, MAX_GENERAL_COMBINERS,
};
pub use command::{
    Capability, Command, CopyTexImage, EvalEnables, EvalMap, MapAttribute, MapDims, ReadPixels,
    TexData, TexImage, TexSubImage,
};
pub use error::{GlError, GlErrorKind, GlResult};
pub use fog::{Fog, FogCoordSource, FogMode, FogParam};
pub use fragment::{
    AlphaTest, Blend, BlendEquation, BlendFactor, ClearMask, ClearValues, ColorMask, CompareFunc,
    DepthRange, DepthTest, Face, FrontFace, HintMode, HintTarget, Hints, LogicOp, OffsetEnables,
    PolygonMode, ScissorBox, ShadeModel, StencilOp, StencilTest, Toggle, Viewport,
};
pub use geometry::{
    max_index, Geometry, MaterialColor, MaterialSide, MaterialSlot, Primitive, VertexMaterials,
};
pub use light::{
    ColorControl, ColorMaterial, ColorMaterialMode, Light, LightModel, LightModelParam, LightParam,
    Material, MaterialParam, Materials, MAX_LIGHTS,
};
pub use matrix::{MatrixMode, MatrixStack, ViewVolume};
pub use pixels::{
    Bitmap, Converted, CopyKind, CopyPixels, DrawPixels, PixelTransfer, PixelTransferParam,
    PixelZoom,
};
pub use point::{PointParam, PointParams, PointSprite};
pub use program::{BuiltIn, SamplerBinding, ShaderProgram, UniformValue};
pub use query::QueryValue;
pub use raster::RasterPos;
pub use state::{
    CurrentValues, FixedState, PolygonModes, TextureUnit, MAX_CLIP_PLANES, MAX_TEXTURE_UNITS,
};
pub use stipple::{LineStipple, PolygonStipple};
pub use texenv::{
    Combine, CombineArg, CombineFunc, CombineOperand, CombineScale, CombineSource, TexEnv,
    TexEnvMode, TexEnvParam, MAX_TEXTURE_LOD_BIAS,
};
pub use texgen::{TexCoord, TexGen, TexGenMode, TexGenParam};
pub use texture::{
    BaseFormat, CompareMode, CubeFace, DepthTextureMode, Filter, Incomplete, PixelData,
    PixelFormat, PixelType, TexFormat, TexLevel, TexParam, TexParams, TextureObject, TextureTarget,
    Wrap,
};
