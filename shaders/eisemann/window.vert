#version 330 core
// Eisemann & Décoret 2008, §3.2: the prefilter passes (N-buffer levels, summed-area-table
// doubling steps) draw a full-window quad whose positions are already clip coordinates;
// each fragment makes one texel.
layout(location = 0) in vec4 position;

void main() {
    gl_Position = position;
}
