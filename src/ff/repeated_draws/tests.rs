use std::sync::Arc;

use crate::ff::script::draws;
use crate::ff::Geometry;

const SETUP: &str = "glBindBuffer(GL_ARRAY_BUFFER, 1);\n\
    glBufferData(GL_ARRAY_BUFFER, 24, (GLfloat[]){0, 0, 1, 0, 0, 1}, GL_STATIC_DRAW);\n\
    glVertexPointer(2, GL_FLOAT, 0, NULL);\n\
    glEnableClientState(GL_VERTEX_ARRAY);\n\
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 2);\n\
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, 6, (GLushort[]){0, 1, 2}, GL_STATIC_DRAW);\n";
const DRAW: &str = "glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, NULL);\n";

#[test]
fn a_repeated_draw_from_unchanged_buffers_gives_the_same_geometry() {
    let g = draws(&format!(
        "{SETUP}{DRAW}{DRAW}glDrawArrays(GL_TRIANGLES, 0, 3);"
    ));
    assert!(Arc::ptr_eq(&g[0], &g[1]));
    assert!(
        !Arc::ptr_eq(&g[1], &g[2]),
        "another draw is another geometry"
    );
    assert_eq!(g[0].indices.as_deref(), Some(&[0, 1, 2][..]));
}

#[test]
fn a_changed_store_or_pointer_makes_a_new_geometry() {
    let sub = "glBufferSubData(GL_ARRAY_BUFFER, 0, 8, (GLfloat[]){-1, -1});\n";
    let g = draws(&format!("{SETUP}{DRAW}{sub}{DRAW}"));
    assert!(!Arc::ptr_eq(&g[0], &g[1]));
    assert_eq!((g[1].positions[0].x, g[1].positions[0].y), (-1.0, -1.0));
    let map = "glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY); glUnmapBuffer(GL_ARRAY_BUFFER);\n";
    let g = draws(&format!("{SETUP}{DRAW}{map}{DRAW}"));
    assert!(!Arc::ptr_eq(&g[0], &g[1]), "a mapping may write the store");
    let moved = "glVertexPointer(2, GL_FLOAT, 0, (const GLvoid *)8);\n";
    let short = "glDrawElements(GL_TRIANGLES, 1, GL_UNSIGNED_SHORT, NULL);\n";
    let g = draws(&format!("{SETUP}{DRAW}{moved}{short}"));
    assert!(!Arc::ptr_eq(&g[0], &g[1]));
    assert_eq!(g[1].positions[0].x, 1.0);
}

#[test]
fn every_object_of_a_frame_repeats_its_own_draw() {
    // Two objects drawn in turn from one buffer, frame after frame.
    let other = "glDrawArrays(GL_TRIANGLES, 0, 3);\n";
    let g = draws(&format!("{SETUP}{DRAW}{other}{DRAW}{other}"));
    assert!(Arc::ptr_eq(&g[0], &g[2]));
    assert!(Arc::ptr_eq(&g[1], &g[3]));
}

#[test]
fn a_draw_from_client_memory_repeats_while_its_bytes_are_the_same() {
    let client = |c: &str| {
        format!(
            "glBindBuffer(GL_ARRAY_BUFFER, 0);\n\
             glSecondaryColorPointer(3, GL_FLOAT, 0, (GLfloat[]){{{c}, 0, 0, 0, 1, 0, 0, 0, 1}});\n\
             glEnableClientState(GL_SECONDARY_COLOR_ARRAY);\n"
        )
    };
    let g = draws(&format!(
        "{SETUP}{}{DRAW}{DRAW}{}{DRAW}",
        client("1"),
        client("0.5")
    ));
    assert!(
        Arc::ptr_eq(&g[0], &g[1]),
        "the same bytes, the same geometry"
    );
    assert!(!Arc::ptr_eq(&g[1], &g[2]), "other bytes, another geometry");
    let red = |g: &Geometry| g.secondary_colors.as_ref().map(|c| c[0].x);
    assert_eq!((red(&g[1]), red(&g[2])), (Some(1.0), Some(0.5)));
}

#[test]
fn a_buffer_call_forgets_only_the_draws_that_read_a_buffer() {
    let client = "glBindBuffer(GL_ARRAY_BUFFER, 0);\n\
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);\n\
        glVertexPointer(2, GL_FLOAT, 0, (GLfloat[]){0, 0, 1, 0, 0, 1});\n";
    let from_memory = "glDrawArrays(GL_TRIANGLES, 0, 3);\n";
    let unrelated = "glBindBuffer(GL_ARRAY_BUFFER, 7);\n\
        glBufferData(GL_ARRAY_BUFFER, 4, NULL, GL_STATIC_DRAW);\n";
    let g = draws(&format!(
        "{SETUP}{DRAW}{client}{from_memory}{unrelated}{from_memory}"
    ));
    assert!(
        Arc::ptr_eq(&g[1], &g[2]),
        "a draw from memory outlives a buffer call"
    );
}
