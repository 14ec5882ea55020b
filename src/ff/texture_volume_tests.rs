//! The depth dimension of texture levels: completeness and generated chains of volumes
//! (GL 1.5 §3.8.8/§3.8.10 with GL 1.2's depth), and glTexImage3D's size checks as Mesa
//! 22.3 llvmpipe gives them (measured natively: MAX_3D_TEXTURE_SIZE 2048, level 11 accepted,
//! level 12 and a width of 3000 INVALID_VALUE).

use super::*;
use crate::ff::GlErrorKind;

fn volume(format: TexFormat, (width, height, depth): (i32, i32, i32)) -> Option<TexLevel> {
    Some(TexLevel {
        internal_format: format,
        width,
        height,
        depth,
        border: 0,
        data: None,
        compressed: None,
        requested: None,
    })
}

/// A mipmapped 8×4×2 chain is 8×4×2, 4×2×1, 2×1×1, 1×1×1; the depth halves like the
/// other dimensions and stops at 1.
#[test]
fn volume_chains_halve_every_dimension() {
    let mut t = TextureObject::new(TextureTarget::Texture2D);
    t.params.min_filter = Filter::LinearMipmapLinear;
    t.params.generate_mipmap = true;
    t.set_level(0, volume(TexFormat::Rgba8, (8, 4, 2)).unwrap());
    t.level_changed(0);
    let sizes: Vec<_> = t
        .levels
        .iter()
        .flatten()
        .map(|l| (l.width, l.height, l.depth))
        .collect();
    assert_eq!(sizes, [(8, 4, 2), (4, 2, 1), (2, 1, 1), (1, 1, 1)]);
    assert_eq!(t.completeness(), Ok(TexFormat::Rgba8));
    // A depth that does not halve breaks the chain.
    t.levels[1] = volume(TexFormat::Rgba8, (4, 2, 2));
    assert_eq!(
        t.completeness(),
        Err(Incomplete::WrongSize {
            level: 1,
            expected: (4, 2, 1),
            found: (4, 2, 2),
        })
    );
}

/// A 1×1×4 base needs levels down to 1×1×1: the depth alone sets p.
#[test]
fn depth_alone_sets_the_chain_length() {
    let mut t = TextureObject::new(TextureTarget::Texture2D);
    t.params.min_filter = Filter::NearestMipmapNearest;
    t.levels = vec![
        volume(TexFormat::Rgb8, (1, 1, 4)),
        volume(TexFormat::Rgb8, (1, 1, 2)),
    ];
    assert_eq!(t.completeness(), Err(Incomplete::MissingLevel(2)));
    t.levels.push(volume(TexFormat::Rgb8, (1, 1, 1)));
    assert!(t.is_complete());
    t.levels[0] = volume(TexFormat::Rgb8, (1, 1, 0));
    assert_eq!(t.completeness(), Err(Incomplete::EmptyBaseLevel));
}

#[test]
fn volume_sizes_follow_mesa() {
    let kind = |level, size, border| check_volume_size(level, size, border).map_err(|e| e.kind);
    assert_eq!(kind(0, [4, 4, 4], 0), Ok(()));
    assert_eq!(kind(11, [1, 1, 1], 0), Ok(()));
    assert_eq!(kind(0, [2048, 1, 1], 0), Ok(()));
    assert_eq!(kind(12, [1, 1, 1], 0), Err(GlErrorKind::InvalidValue));
    assert_eq!(kind(-1, [1, 1, 1], 0), Err(GlErrorKind::InvalidValue));
    assert_eq!(kind(0, [3000, 1, 1], 0), Err(GlErrorKind::InvalidValue));
    assert_eq!(kind(0, [4, -1, 4], 0), Err(GlErrorKind::InvalidValue));
    assert_eq!(kind(0, [4, 4, 4], 2), Err(GlErrorKind::InvalidValue));
    assert_eq!(
        volume_size(PixelFormat::Rgba, PixelType::UnsignedByte, 5, 3, 7),
        5 * 3 * 7 * 4
    );
}

mod calls {
    //! glTexImage3D, glTexSubImage3D, glCopyTexSubImage3D, the proxy, the 3D enable and
    //! binding through `FixedState::apply`, with the errors Mesa 22.3 gives (measured:
    //! `tests/c/tex3d.c`).

    use std::sync::Arc;

    use crate::ff::attrib::{AttribGroup, AttribMask};
    use crate::ff::glenum::registry as r;
    use crate::ff::texture_calls::CopyTexSubImage;
    use crate::ff::{
        Capability, Command, FixedState, GlErrorKind, PixelFormat, PixelType, TexData, TexFormat,
        TexImage, TexParam, TexSubImage, TextureTarget, Wrap,
    };

    fn image(level: i32, size: (i32, i32, i32), format: TexFormat, data: TexData) -> TexImage {
        TexImage {
            requested: None,
            target: TextureTarget::Texture3D,
            level,
            internal_format: format,
            width: size.0,
            height: size.1,
            depth: size.2,
            border: 0,
            format: if format.is_depth() {
                PixelFormat::DepthComponent
            } else {
                PixelFormat::Luminance
            },
            ty: PixelType::UnsignedByte,
            data,
        }
    }

    /// A 2×2×3 LUMINANCE8 volume whose texel (x, y, z) is 10·z + 2·y + x.
    fn with_volume() -> FixedState {
        let mut s = FixedState::new();
        let bytes: Vec<u8> = (0..3)
            .flat_map(|z| (0..4).map(move |i| 10 * z + i))
            .collect();
        let t = image(0, (2, 2, 3), TexFormat::Luminance8, bytes.into());
        s.apply(&Command::TexImage(t)).unwrap();
        s
    }

    fn kind(s: &mut FixedState, c: Command) -> Option<GlErrorKind> {
        s.apply(&c).err().map(|e| e.kind)
    }

    #[test]
    fn images_are_checked_as_mesa_checks_them() {
        let mut s = FixedState::new();
        let null =
            |level, size, format| Command::TexImage(image(level, size, format, TexData::Null));
        use TexFormat::{DepthComponent24, Rgba8};
        assert_eq!(kind(&mut s, null(0, (4, 4, 4), Rgba8)), None);
        assert_eq!(kind(&mut s, null(11, (1, 1, 1), Rgba8)), None);
        assert_eq!(kind(&mut s, null(0, (0, 0, 0), Rgba8)), None);
        assert_eq!(kind(&mut s, null(0, (3, 5, 7), Rgba8)), None);
        let value = Some(GlErrorKind::InvalidValue);
        assert_eq!(kind(&mut s, null(12, (1, 1, 1), Rgba8)), value);
        assert_eq!(kind(&mut s, null(0, (4, 4, -1), Rgba8)), value);
        assert_eq!(kind(&mut s, null(0, (2049, 1, 1), Rgba8)), value);
        // MAX_3D_TEXTURE_SIZE >> level: level 1 holds at most 1024.
        assert_eq!(kind(&mut s, null(1, (2048, 1, 1), Rgba8)), value);
        assert_eq!(kind(&mut s, null(1, (1024, 1, 1), Rgba8)), None);
        // No depth textures in 3D (ARB_depth_texture), whatever the data.
        let op = Some(GlErrorKind::InvalidOperation);
        assert_eq!(kind(&mut s, null(0, (4, 4, 4), DepthComponent24)), op);
        let mut stencil = image(0, (1, 1, 1), Rgba8, TexData::Null);
        stencil.format = PixelFormat::StencilIndex;
        assert_eq!(kind(&mut s, Command::TexImage(stencil)), op);
        // The data holds depth images.
        let short = image(0, (2, 2, 2), TexFormat::Luminance8, vec![0u8; 7].into());
        assert_eq!(kind(&mut s, Command::TexImage(short)), value);
    }

    fn sub(level: i32, at: (i32, i32, i32), size: (i32, i32, i32), data: Vec<u8>) -> Command {
        Command::TexSubImage3D(TexSubImage {
            face: None,
            level,
            x: at.0,
            y: at.1,
            z: at.2,
            width: size.0,
            height: size.1,
            depth: size.2,
            format: PixelFormat::Luminance,
            ty: PixelType::UnsignedByte,
            data: Some(Arc::from(data)),
        })
    }

    #[test]
    fn sub_images_patch_image_by_image() {
        let mut s = with_volume();
        s.apply(&sub(0, (1, 0, 1), (1, 2, 2), vec![91, 92, 93, 94]))
            .unwrap();
        let level = s.default_3d.level(0).unwrap();
        let bytes = &level.data.as_ref().unwrap().bytes;
        assert_eq!(
            bytes[..],
            [0, 1, 2, 3, 10, 91, 12, 92, 20, 93, 22, 94],
            "images 1 and 2, column 1"
        );
        let value = Some(GlErrorKind::InvalidValue);
        assert_eq!(
            kind(&mut s, sub(0, (0, 0, 2), (1, 1, 2), vec![0; 2])),
            value
        );
        assert_eq!(kind(&mut s, sub(0, (0, 0, -1), (1, 1, 1), vec![0])), value);
        assert_eq!(kind(&mut s, sub(0, (0, 0, 0), (1, 1, -1), vec![])), value);
        assert_eq!(kind(&mut s, sub(12, (0, 0, 0), (1, 1, 1), vec![0])), value);
        // An empty region at the edge is none, one past it is.
        assert_eq!(kind(&mut s, sub(0, (2, 0, 0), (0, 1, 1), vec![])), None);
        assert_eq!(kind(&mut s, sub(0, (3, 0, 0), (0, 1, 1), vec![])), value);
        let op = Some(GlErrorKind::InvalidOperation);
        assert_eq!(kind(&mut s, sub(1, (0, 0, 0), (1, 1, 1), vec![0])), op);
    }

    #[test]
    fn copies_land_in_one_image() {
        let mut s = with_volume();
        let copy = |level, zoffset, width| {
            Command::CopyTexSubImage(CopyTexSubImage {
                target: TextureTarget::Texture3D,
                level,
                xoffset: 0,
                yoffset: 0,
                zoffset,
                x: 0,
                y: 0,
                width,
                height: 1,
            })
        };
        assert_eq!(kind(&mut s, copy(0, 3, 1)), Some(GlErrorKind::InvalidValue));
        assert_eq!(
            kind(&mut s, copy(0, -1, 1)),
            Some(GlErrorKind::InvalidValue)
        );
        assert_eq!(
            kind(&mut s, copy(0, 0, -1)),
            Some(GlErrorKind::InvalidValue)
        );
        assert_eq!(
            kind(&mut s, copy(12, 0, 1)),
            Some(GlErrorKind::InvalidValue)
        );
        assert_eq!(
            kind(&mut s, copy(1, 0, 1)),
            Some(GlErrorKind::InvalidOperation)
        );
        assert!(s.default_3d.level(0).unwrap().data.is_some());
        assert_eq!(kind(&mut s, copy(0, 2, 2)), None);
        assert!(s.default_3d.level(0).unwrap().data.is_none());
    }

    /// GL 1.5 §3.8.15: 3D wins over 2D, 2D over 1D; each target keeps its own binding.
    #[test]
    fn the_3d_enable_wins_and_binds_its_own_name() {
        let mut s = with_volume();
        for c in [
            Command::Enable(Capability::Texture1D),
            Command::Enable(Capability::Texture2D),
            Command::BindTexture {
                target: TextureTarget::Texture3D,
                name: 6,
            },
        ] {
            s.apply(&c).unwrap();
        }
        assert_eq!(s.units[0].enabled_target(), Some(TextureTarget::Texture2D));
        s.apply(&Command::Enable(Capability::Texture3D)).unwrap();
        assert_eq!(s.units[0].enabled_target(), Some(TextureTarget::Texture3D));
        assert_eq!(s.get_integerv(r::TEXTURE_BINDING_3D), Ok(vec![6]));
        assert_eq!(s.get_integerv(r::TEXTURE_BINDING_2D), Ok(vec![0]));
        assert_eq!(s.is_enabled(r::TEXTURE_3D), Ok(true));
        // A name made by a 3D bind is no 2D texture.
        assert_eq!(
            kind(
                &mut s,
                Command::BindTexture {
                    target: TextureTarget::Texture2D,
                    name: 6
                }
            ),
            Some(GlErrorKind::InvalidOperation)
        );
        // Deleting the bound name reverts the binding to 0.
        s.apply(&Command::DeleteTextures(vec![6])).unwrap();
        assert_eq!(s.units[0].bound_3d, 0);
        assert_eq!(s.get_integerv(r::MAX_3D_TEXTURE_SIZE), Ok(vec![2048]));
    }

    #[test]
    fn level_queries_answer_the_depth() {
        let s = with_volume();
        let q = |target, level, pname| {
            s.get_tex_level_parameter(target, level, pname)
                .map(|v| v[0].as_int())
        };
        assert_eq!(q(r::TEXTURE_3D, 0, r::TEXTURE_DEPTH), Ok(3));
        assert_eq!(q(r::TEXTURE_3D, 0, r::TEXTURE_WIDTH), Ok(2));
        assert_eq!(q(r::TEXTURE_3D, 11, r::TEXTURE_DEPTH), Ok(0));
        assert_eq!(
            q(r::TEXTURE_3D, 12, r::TEXTURE_DEPTH),
            Err(GlErrorKind::InvalidValue)
        );
        // A 2D level is one image deep; an unspecified one 0, up to level 14.
        assert_eq!(q(r::TEXTURE_2D, 0, r::TEXTURE_DEPTH), Ok(0));
        assert_eq!(q(r::TEXTURE_2D, 14, r::TEXTURE_DEPTH), Ok(0));
        assert_eq!(
            q(r::TEXTURE_2D, 15, r::TEXTURE_DEPTH),
            Err(GlErrorKind::InvalidValue)
        );
    }

    #[test]
    fn wrap_r_is_kept_for_every_target_and_pushed_with_the_texture_bit() {
        let mut s = with_volume();
        let wrap = |s: &FixedState, target| s.get_tex_parameter(target, r::TEXTURE_WRAP_R);
        assert_eq!(
            wrap(&s, r::TEXTURE_3D).unwrap()[0].as_int(),
            r::REPEAT as i32
        );
        for c in [
            Command::TexParameter {
                target: TextureTarget::Texture2D,
                param: TexParam::WrapR(Wrap::Clamp),
            },
            Command::Enable(Capability::Texture3D),
            Command::PushAttrib(AttribMask::of(&[AttribGroup::Texture])),
            Command::TexParameter {
                target: TextureTarget::Texture3D,
                param: TexParam::WrapR(Wrap::ClampToEdge),
            },
            Command::BindTexture {
                target: TextureTarget::Texture3D,
                name: 7,
            },
            Command::Disable(Capability::Texture3D),
        ] {
            s.apply(&c).unwrap();
        }
        assert_eq!(
            wrap(&s, r::TEXTURE_2D).unwrap()[0].as_int(),
            r::CLAMP as i32
        );
        s.apply(&Command::PopAttrib).unwrap();
        assert_eq!(s.units[0].bound_3d, 0);
        assert!(s.units[0].texture_3d);
        assert_eq!(s.default_3d.params.wrap_r, Wrap::Repeat);
    }

    #[test]
    fn proxies_check_without_an_image() {
        let mut s = FixedState::new();
        let proxy = |level, size| {
            Command::ProxyTexImage(image(level, size, TexFormat::Rgba8, TexData::Null))
        };
        let width = |s: &FixedState| {
            s.get_tex_level_parameter(r::PROXY_TEXTURE_3D, 0, r::TEXTURE_WIDTH)
                .map(|v| v[0].as_int())
        };
        s.apply(&proxy(0, (64, 32, 16))).unwrap();
        assert_eq!(width(&s), Ok(64));
        let depth = s.get_tex_level_parameter(r::PROXY_TEXTURE_3D, 0, r::TEXTURE_DEPTH);
        assert_eq!(depth.map(|v| v[0].as_int()), Ok(16));
        // Too large: no error, the level unspecified.
        s.apply(&proxy(0, (4096, 1, 1))).unwrap();
        assert_eq!(width(&s), Ok(0));
        let format = s.get_tex_level_parameter(r::PROXY_TEXTURE_3D, 0, r::TEXTURE_INTERNAL_FORMAT);
        assert_eq!(format.map(|v| v[0].as_int()), Ok(r::RGBA as i32));
        // The arguments are still errors, and change nothing.
        s.apply(&proxy(0, (8, 8, 8))).unwrap();
        assert_eq!(
            kind(&mut s, proxy(0, (-1, 1, 1))),
            Some(GlErrorKind::InvalidValue)
        );
        assert_eq!(
            kind(&mut s, proxy(12, (1, 1, 1))),
            Some(GlErrorKind::InvalidValue)
        );
        assert_eq!(width(&s), Ok(8));
        // No unit samples the proxy.
        assert!(s.default_3d.level(0).is_none());
        assert_eq!(
            s.get_tex_parameter(r::PROXY_TEXTURE_3D, r::TEXTURE_WRAP_R),
            Err(GlErrorKind::InvalidEnum)
        );
    }

    /// A display list keeps glTexImage3D with the data read when it is compiled, and runs
    /// a proxy image at once.
    #[test]
    fn lists_keep_the_image_and_run_the_proxy_at_once() {
        let src = "glPixelStorei(GL_UNPACK_ALIGNMENT, 1);\n\
                   glNewList(1, GL_COMPILE);\n\
                   glTexImage3D(GL_TEXTURE_3D, 0, GL_LUMINANCE8, 1, 1, 2, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, (GLubyte[]){5, 6});\n\
                   glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA8, 8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);\n\
                   glEndList();\n";
        let cmds = crate::ff::script::parse(src).unwrap();
        assert!(matches!(cmds[..], [Command::ProxyTexImage(_)]), "{cmds:?}");
        let called = crate::ff::script::parse(&format!("{src}glCallList(1);\n")).unwrap();
        let Some(Command::TexImage(t)) = called.last() else {
            panic!("{called:?}");
        };
        assert_eq!(t.data.bytes().map(|b| b.to_vec()), Some(vec![5, 6]));
    }
}

/// The fuzzer's seed for volumes parses, prints and parses again to the same commands.
#[test]
fn the_volume_seed_round_trips() {
    let text = include_str!("../../fuzz/seeds/script/volume-images");
    let cmds = crate::ff::script::parse(text).unwrap();
    let Some(crate::ff::Command::TexImage(t)) = cmds.get(1) else {
        panic!("{cmds:?}");
    };
    assert_eq!(
        t.data.bytes().map(|b| b.to_vec()),
        Some(vec![8, 9, 10, 11, 14, 15, 16, 17])
    );
    let printed = crate::ff::script::print(&cmds);
    assert_eq!(
        crate::ff::script::parse(&printed).unwrap(),
        cmds,
        "{printed}"
    );
}
