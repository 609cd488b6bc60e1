import { defineConfig } from 'vite';
import { resolve } from 'node:path';

// Relative base: the built site works from any sub-path (a course page, a USB stick).
export default defineConfig({
  base: './',
  build: {
    target: 'es2022',
    // three.js's WebGLRenderer is most of the hero chunk (about 170 kB gzipped); it loads once.
    chunkSizeWarningLimit: 700,
    rollupOptions: {
      input: {
        index: resolve(import.meta.dirname, 'index.html'),
        embed: resolve(import.meta.dirname, 'embed.html'),
      },
    },
  },
  server: { host: '127.0.0.1' },
  preview: { host: '127.0.0.1' },
  test: {
    include: ['tests/unit/**/*.test.js'],
    environment: 'node',
  },
});
