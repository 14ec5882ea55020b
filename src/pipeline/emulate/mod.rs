//! The emulated path: `FixedState` → `ShaderKey` → generated GLSL → a program cached by key,
//! on a core 3.3 context.

pub mod cache;
pub mod glsl;
