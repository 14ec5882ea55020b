//! The `[shadow]` keys of `occlusion-textures` (Eisemann & Décoret 2008): how many slices,
//! how the occlusion textures are prefiltered (§3.2) and how the slices' contributions are
//! combined (§3.3). The values are read by serde: an unknown one is refused with the valid
//! ones listed.

use serde::Deserialize;

/// `[shadow] prefilter`: the box filter of §3.2.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Prefilter {
    /// glGenerateMipmap; a box of 2^l texels read at level l, trilinearly.
    #[default]
    Mipmap,
    /// Décoret's N-buffers: level l holds the box filter of 2^l × 2^l texels at full
    /// resolution; intermediate sizes interpolated between levels.
    Nbuffers,
    /// A summed-area table in 32-bit floats: the exact box.
    Sat,
}

/// `[shadow] combine`: how the slices' blocked fractions I_k make a visibility (§3.3).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Combine {
    /// Equation 5: V = Π (1 − I_k).
    #[default]
    Probabilistic,
    /// V = 1 − min(1, Σ I_k).
    Sum,
    /// V = 1 − max I_k.
    Max,
}

/// The slice counts the technique takes (the paper's "four to 16 slices").
pub const SLICE_COUNTS: [u32; 3] = [4, 8, 16];
