#!/usr/bin/env node
// Writes the single-file pages after the ordinary build (npm run build): dist/offline/index.html,
// the lecture, dist/offline/embed.html, one panel (?panel=ID), and dist/offline/homework.html, the
// homework page (?sheet=CODE), whose panels are frames of the embed beside it. Each is one HTML file with
// everything in it, so the folder can be carried on a USB stick and opened from disk.
import { build } from 'vite';

for (const page of ['index', 'embed', 'homework']) {
  process.env.FRESNEL_LAB_SINGLE_FILE = page; // read by vite.config.js
  await build({ logLevel: 'warn' });
}
