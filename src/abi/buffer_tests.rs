//! The buffer objects of `ff::buffers`, driven through the C front end's argument reader
//! (`cargs::CCall`), so that each call's GL error shows as a C program would see it.

use crate::ff::api::Entry;
use crate::ff::buffers::*;
use crate::ff::client::ArrayData;
use crate::ff::front::Reply;
use crate::ff::glenum::value_of;
use crate::ff::glenum::GlEnum;

#[test]
fn token_tables_hold_the_registry_values() {
    fn check<T: GlEnum>() {
        for (name, value, _) in T::TABLE {
            assert_eq!(value_of(name), Some(*value), "{name}");
        }
    }
    check::<Target>();
    check::<Usage>();
    check::<Access>();
    check::<BufferParam>();
}

/// The C front end's arguments, built here so that the GL error of each call shows.
mod c {
    pub use crate::abi::cargs::{CArg, CCall};
}

fn run(bufs: &mut Buffers, entry: Entry, args: &[c::CArg]) -> Result<Reply, GlErrorKind> {
    let call = c::CCall {
        entry,
        args,
        unpack: crate::ff::pixel_store::Packing::DEFAULT,
        access: Default::default(),
        unsupported: Default::default(),
    };
    bufs.call(&call, &crate::abi::cargs::ProgramMemory)
}

use crate::ff::GlErrorKind;
use c::CArg::{Int, Ptr};

const ARRAY: i64 = 0x8892;
const ELEMENT: i64 = 0x8893;
const STATIC_DRAW: i64 = 0x88E4;
const WRITE_ONLY: i64 = 0x88B9;
const BUFFER_SIZE: i64 = 0x8764;
const BUFFER_USAGE: i64 = 0x8765;
const NULL: c::CArg = Ptr(std::ptr::null(), crate::abi::cargs::CElem::Void);

fn ptr(bytes: &[u8]) -> c::CArg {
    Ptr(bytes.as_ptr().cast(), crate::abi::cargs::CElem::Void)
}

/// Buffer 1 bound to ARRAY_BUFFER with the bytes 0..16.
fn filled() -> Buffers {
    let mut b = Buffers::default();
    let data: Vec<u8> = (0..16).collect();
    run(&mut b, Entry::BindBuffer, &[Int(ARRAY), Int(1)]).unwrap();
    run(
        &mut b,
        Entry::BufferData,
        &[Int(ARRAY), Int(16), ptr(&data), Int(STATIC_DRAW)],
    )
    .unwrap();
    b
}

#[test]
fn generated_names_follow_the_largest_and_are_buffers_once_bound() {
    let mut b = Buffers::default();
    let Ok(Reply::Write { arg: 1, bytes }) = run(&mut b, Entry::GenBuffers, &[Int(2), NULL]) else {
        panic!("glGenBuffers writes names");
    };
    assert_eq!(
        bytes,
        [1u32, 2]
            .iter()
            .flat_map(|n| n.to_ne_bytes())
            .collect::<Vec<_>>()
    );
    assert_eq!(run(&mut b, Entry::IsBuffer, &[Int(1)]), Ok(Reply::Value(0)));
    run(&mut b, Entry::BindBufferARB, &[Int(ELEMENT), Int(1)]).unwrap();
    assert_eq!(
        run(&mut b, Entry::IsBufferARB, &[Int(1)]),
        Ok(Reply::Value(1))
    );
    assert_eq!(b.bound.element, 1);
    let names = [1u32];
    let p = Ptr(names.as_ptr().cast(), crate::abi::cargs::CElem::UInt);
    run(&mut b, Entry::DeleteBuffers, &[Int(1), p]).unwrap();
    assert_eq!(run(&mut b, Entry::IsBuffer, &[Int(1)]), Ok(Reply::Value(0)));
    assert_eq!(b.bound.element, 0, "deleting a bound buffer unbinds it");
    assert_eq!(
        run(&mut b, Entry::GenBuffers, &[Int(-1), NULL]),
        Err(GlErrorKind::InvalidValue)
    );
    assert_eq!(
        run(&mut b, Entry::DeleteBuffers, &[Int(-1), NULL]),
        Err(GlErrorKind::InvalidValue)
    );
}

#[test]
fn names_are_not_handed_out_twice() {
    let mut b = Buffers::default();
    run(&mut b, Entry::BindBuffer, &[Int(ARRAY), Int(7)]).unwrap();
    let Ok(Reply::Write { bytes, .. }) = run(&mut b, Entry::GenBuffersARB, &[Int(1), NULL]) else {
        panic!("glGenBuffers writes names");
    };
    assert_eq!(bytes, 8u32.to_ne_bytes());
    let Ok(Reply::Write { bytes, .. }) = run(&mut b, Entry::GenBuffers, &[Int(1), NULL]) else {
        panic!("glGenBuffers writes names");
    };
    assert_eq!(
        bytes,
        9u32.to_ne_bytes(),
        "a generated, unbound name stays taken"
    );
    run(
        &mut b,
        Entry::BindBuffer,
        &[Int(ARRAY), Int(u32::MAX as i64 - 1)],
    )
    .unwrap();
    assert_eq!(
        run(&mut b, Entry::GenBuffers, &[Int(2), NULL]),
        Err(GlErrorKind::InvalidValue)
    );
}

#[test]
fn bad_targets_usages_and_access_are_invalid_enum() {
    let mut b = filled();
    let e = Err(GlErrorKind::InvalidEnum);
    assert_eq!(run(&mut b, Entry::BindBuffer, &[Int(0x0DE1), Int(1)]), e);
    assert_eq!(
        run(
            &mut b,
            Entry::BufferData,
            &[Int(0x0DE1), Int(4), NULL, Int(STATIC_DRAW)]
        ),
        e
    );
    assert_eq!(
        run(
            &mut b,
            Entry::BufferData,
            &[Int(ARRAY), Int(4), NULL, Int(0x1234)]
        ),
        e
    );
    assert_eq!(run(&mut b, Entry::MapBuffer, &[Int(ARRAY), Int(0x1234)]), e);
    assert_eq!(
        run(
            &mut b,
            Entry::GetBufferParameteriv,
            &[Int(ARRAY), Int(0x1234), NULL]
        ),
        e
    );
}

#[test]
fn buffer_zero_bound_is_invalid_operation() {
    let mut b = Buffers::default();
    let e = Err(GlErrorKind::InvalidOperation);
    assert_eq!(
        run(
            &mut b,
            Entry::BufferData,
            &[Int(ARRAY), Int(4), NULL, Int(STATIC_DRAW)]
        ),
        e
    );
    assert_eq!(
        run(
            &mut b,
            Entry::BufferSubData,
            &[Int(ELEMENT), Int(0), Int(0), NULL]
        ),
        e
    );
    assert_eq!(
        run(&mut b, Entry::MapBuffer, &[Int(ARRAY), Int(WRITE_ONLY)]),
        e
    );
    assert_eq!(run(&mut b, Entry::UnmapBuffer, &[Int(ARRAY)]), e);
    assert_eq!(
        run(
            &mut b,
            Entry::GetBufferParameteriv,
            &[Int(ARRAY), Int(BUFFER_SIZE), NULL]
        ),
        e
    );
}

#[test]
fn sizes_and_ranges_are_checked() {
    let mut b = filled();
    let v = Err(GlErrorKind::InvalidValue);
    let four = [9u8; 4];
    assert_eq!(
        run(
            &mut b,
            Entry::BufferData,
            &[Int(ARRAY), Int(-1), NULL, Int(STATIC_DRAW)]
        ),
        v
    );
    for (offset, size) in [(-1, 4), (0, -1), (13, 4)] {
        assert_eq!(
            run(
                &mut b,
                Entry::BufferSubData,
                &[Int(ARRAY), Int(offset), Int(size), ptr(&four)]
            ),
            v,
            "offset {offset} size {size}"
        );
        assert_eq!(
            run(
                &mut b,
                Entry::GetBufferSubData,
                &[Int(ARRAY), Int(offset), Int(size), NULL]
            ),
            v
        );
    }
    run(
        &mut b,
        Entry::BufferSubData,
        &[Int(ARRAY), Int(12), Int(4), ptr(&four)],
    )
    .unwrap();
    assert_eq!(b.read(1, 10, 6), Some(&[10, 11, 9, 9, 9, 9][..]));
    assert_eq!(
        run(
            &mut b,
            Entry::GetBufferSubData,
            &[Int(ARRAY), Int(2), Int(3), NULL]
        ),
        Ok(Reply::Write {
            arg: 3,
            bytes: vec![2, 3, 4]
        })
    );
    assert_eq!(
        run(
            &mut b,
            Entry::GetBufferParameteriv,
            &[Int(ARRAY), Int(BUFFER_SIZE), NULL]
        ),
        Ok(Reply::Write {
            arg: 2,
            bytes: 16i32.to_ne_bytes().to_vec()
        })
    );
    assert_eq!(
        run(
            &mut b,
            Entry::GetBufferParameteriv,
            &[Int(ARRAY), Int(BUFFER_USAGE), NULL]
        ),
        Ok(Reply::Write {
            arg: 2,
            bytes: (STATIC_DRAW as i32).to_ne_bytes().to_vec()
        })
    );
}

#[test]
fn mapping_rules_and_writes_through_the_map() {
    let mut b = filled();
    let op = Err(GlErrorKind::InvalidOperation);
    assert_eq!(run(&mut b, Entry::UnmapBuffer, &[Int(ARRAY)]), op);
    let Ok(Reply::Address(a)) = run(&mut b, Entry::MapBuffer, &[Int(ARRAY), Int(WRITE_ONLY)])
    else {
        panic!("glMapBuffer gives an address");
    };
    assert_eq!(b.get(1).and_then(|x| x.mapped), Some(Access::WriteOnly));
    assert_eq!(
        run(&mut b, Entry::MapBufferARB, &[Int(ARRAY), Int(WRITE_ONLY)]),
        op
    );
    let four = [7u8; 4];
    assert_eq!(
        run(
            &mut b,
            Entry::BufferSubData,
            &[Int(ARRAY), Int(0), Int(4), ptr(&four)]
        ),
        op
    );
    assert_eq!(
        run(
            &mut b,
            Entry::GetBufferSubData,
            &[Int(ARRAY), Int(0), Int(4), NULL]
        ),
        op
    );
    // SAFETY: the address is the 16-byte store of buffer 1, mapped.
    unsafe { *(a as *mut u8).add(5) = 200 };
    assert_eq!(
        run(&mut b, Entry::UnmapBufferARB, &[Int(ARRAY)]),
        Ok(Reply::Value(1))
    );
    assert_eq!(b.read(1, 4, 2), Some(&[4, 200][..]));
    assert_eq!(run(&mut b, Entry::UnmapBuffer, &[Int(ARRAY)]), op);
}

#[test]
fn offsets_are_captured_when_a_buffer_is_bound() {
    let b = filled();
    let call = c::CCall {
        entry: Entry::VertexPointer,
        args: &[
            Int(3),
            Int(0x1406),
            Int(0),
            Ptr(12 as *const _, crate::abi::cargs::CElem::Void),
        ],
        unpack: crate::ff::pixel_store::Packing::DEFAULT,
        access: Default::default(),
        unsupported: Default::default(),
    };
    assert_eq!(
        Buffers::source(&call, 3, b.bound.array),
        Ok(ArrayData::Buffer {
            name: 1,
            offset: 12
        })
    );
    assert_eq!(b.read(1, 12, 4), Some(&[12, 13, 14, 15][..]));
    assert_eq!(b.read(1, 13, 4), None);
}
