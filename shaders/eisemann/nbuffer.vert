#version 330 core
// Eisemann & Décoret 2008, §3.2 (N-buffers, after Décoret 2005): a full-window quad whose
// positions are already clip coordinates; each fragment makes one texel of a level.
layout(location = 0) in vec4 position;

void main() {
    gl_Position = position;
}
