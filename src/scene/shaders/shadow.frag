#version 450 core
// Shadow pass: depth only.
void main() {}
