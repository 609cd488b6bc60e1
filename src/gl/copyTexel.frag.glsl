// A full-screen copy of a texture of the canvas's size, texel for texel (createBackdrop.js draws
// the kept sky with it; the frame benchmark times it as the floor of any full-screen pass).
precision highp float;
uniform sampler2D uPicture;
out vec4 fragColor;
void main() {
  fragColor = texelFetch(uPicture, ivec2(gl_FragCoord.xy), 0);
}
