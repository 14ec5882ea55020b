//! Colour-index state in an RGBA context (GL 1.5 §2.7, §4.2): the layer's buffers are RGBA
//! (RGBA_MODE is TRUE), so the current index, the clear index and the index write mask
//! draw nothing; they are kept and answered as Mesa 22.3 keeps them.
//!
//! - The current index (glIndex*) is a float as given, inside glBegin/glEnd and out;
//!   GL default 1.
//! - The clear index is an unsigned integer: glClearIndex(c) stores c truncated towards
//!   zero and wrapped to 32 bits (Mesa's `(GLuint) c`; −1.5 is 2³² − 1, which reads back
//!   as −1), and glPopAttrib, when the saved index differs from the current one, sets it
//!   again from that integer made a float, so 2³² − 1 comes back as 0 (measured,
//!   `tests/c/color_index.c`).
//! - The index write mask is 32 bits (GL default all ones, which read back as −1).

/// glClearIndex's value as Mesa stores it: ⌊c⌋ towards zero, wrapped to 32 bits (NaN: 0).
pub fn clear_index(c: f32) -> u32 {
    (c as i64) as u32
}

/// The clear index glPopAttrib restores from the saved one: Mesa calls glClearIndex with
/// the saved integer as a float, which rounds 2³² − 1 up to 2³² (stored as 0).
pub fn restored_clear_index(saved: u32) -> u32 {
    clear_index(saved as f32)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clear_indices_truncate_wrap_and_restore_as_mesa_does() {
        assert_eq!(clear_index(2.6), 2);
        assert_eq!(clear_index(-1.5), u32::MAX);
        assert_eq!(clear_index(f32::NAN), 0);
        assert_eq!(restored_clear_index(7), 7);
        assert_eq!(restored_clear_index(u32::MAX), 0);
    }
}
