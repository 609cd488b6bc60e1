// A texture with every mip level supplied by the caller (no generateMipmap): the shader then
// samples exactly what a technique stored. WebGL2, immutable storage (texStorage2D), as three.js
// uploads a DataTexture with mipmaps.

/** GL internal format, format and type for a component layout ('RGBA' | 'RG' | 'R') and a storage type. */
export function textureFormat(gl, layout, type) {
  const formats = { RGBA: gl.RGBA, RG: gl.RG, R: gl.RED };
  const internal = {
    u8: { RGBA: gl.RGBA8, RG: gl.RG8, R: gl.R8 },
    f16: { RGBA: gl.RGBA16F, RG: gl.RG16F, R: gl.R16F },
    f32: { RGBA: gl.RGBA32F, RG: gl.RG32F, R: gl.R32F },
  };
  const types = { u8: gl.UNSIGNED_BYTE, f16: gl.HALF_FLOAT, f32: gl.FLOAT };
  if (!internal[type]?.[layout]) throw new RangeError(`No texture format for ${layout} ${type}.`);
  return { internalFormat: internal[type][layout], format: formats[layout], type: types[type] };
}

/**
 * levels: [{ data, width, height }], level 0 first (u8 as Uint8Array, f16 as Uint16Array of
 * binary16 bits, f32 as Float32Array). Trilinear filtering, repeat wrap, `anisotropy` taps when
 * EXT_texture_filter_anisotropic is there (1: off).
 */
export function createMipTexture(gl, { format: layout, type, mipmaps }, anisotropy = 1) {
  const { internalFormat, format, type: glType } = textureFormat(gl, layout, type);
  const texture = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1); // rows of 1- and 2-byte texels are not padded to 4
  gl.texStorage2D(gl.TEXTURE_2D, mipmaps.length, internalFormat, mipmaps[0].width, mipmaps[0].height);
  mipmaps.forEach(({ data, width, height }, level) => {
    gl.texSubImage2D(gl.TEXTURE_2D, level, 0, 0, width, height, format, glType, data);
  });
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.REPEAT);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.REPEAT);
  setAnisotropy(gl, texture, anisotropy);
  gl.bindTexture(gl.TEXTURE_2D, null);
  return texture;
}

const maxima = new WeakMap(); // per context: a getParameter waits for the GPU, so it is asked once

/** The most anisotropic taps this GPU offers (1 without EXT_texture_filter_anisotropic). */
export function maxAnisotropy(gl) {
  if (!maxima.has(gl)) {
    const ext = gl.getExtension('EXT_texture_filter_anisotropic');
    maxima.set(gl, ext ? gl.getParameter(ext.MAX_TEXTURE_MAX_ANISOTROPY_EXT) : 1);
  }
  return maxima.get(gl);
}

export function setAnisotropy(gl, texture, anisotropy) {
  const ext = gl.getExtension('EXT_texture_filter_anisotropic');
  if (!ext) return;
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texParameterf(gl.TEXTURE_2D, ext.TEXTURE_MAX_ANISOTROPY_EXT, Math.min(anisotropy, maxAnisotropy(gl)));
}
