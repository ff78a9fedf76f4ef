import type { Plugin } from 'vite';
import { VitePWA } from 'vite-plugin-pwa';
import { levelTextsPlugin } from './scripts/level-texts-plugin.ts';
import { configDefaults, defineConfig } from 'vitest/config';

/**
 * base './' so the built app works from any folder of a static host. The service worker
 * (Workbox, through vite-plugin-pwa) precaches every file of the build, so after one visit
 * the app opens and plays without a network; hash routes mean every page is index.html.
 * The USB-stick build (vite.usb.config.ts) has no service worker: file:// pages cannot
 * register one.
 */

/**
 * The built app's Content-Security-Policy: scripts only from the app's own files (no inline
 * script, no eval), workers from them too, nothing from other hosts. Styles may be inline
 * (lit sets style attributes and the three.js canvas is sized with them); images and fetches
 * may be data: and blob: URLs (inlined assets, rendered PNGs, QR codes, downloads). Only in
 * the build: the dev server's hot reload needs a websocket and inline code.
 */
const CONTENT_SECURITY_POLICY = [
  "default-src 'self'",
  "script-src 'self'",
  "worker-src 'self' blob:",
  "style-src 'self' 'unsafe-inline'",
  "img-src 'self' data: blob:",
  "font-src 'self' data:",
  "connect-src 'self' data: blob:",
  "object-src 'none'",
  "base-uri 'self'",
  "form-action 'none'",
].join('; ');

function contentSecurityPolicy(): Plugin {
  return {
    name: 'content-security-policy',
    apply: 'build',
    transformIndexHtml: () => [{ tag: 'meta', attrs: { 'http-equiv': 'Content-Security-Policy', content: CONTENT_SECURITY_POLICY }, injectTo: 'head-prepend' }],
  };
}

export default defineConfig({
  base: './',
  worker: { format: 'es' },
  // The manifest is what scripts/first-load.ts reads to hold a student's first load to its
  // budget (`npm run check:size`, part of `npm test`).
  build: {
    target: 'es2022',
    outDir: 'dist',
    manifest: true,
    // The task figures are files of their own, fetched when a task shows one, not data URLs
    // in the first load's script (src/ui/game/figure-urls.ts); the USB build inlines them all.
    assetsInlineLimit: (file) => (file.includes('/assets/figures/') ? false : undefined),
  },
  preview: { host: '127.0.0.1', port: 4173 },
  plugins: [
    levelTextsPlugin(),
    contentSecurityPolicy(),
    VitePWA({
      // src/app/offline-copy.ts registers the worker itself, to tell the Menu whether the
      // files could be stored. 'prompt' leaves the update policy to the options below.
      registerType: 'prompt',
      injectRegister: false,
      includeAssets: ['icons/*.png'],
      manifest: {
        name: 'Ray Tracer Quest',
        short_name: 'Ray Tracer',
        description: 'Learn ray tracing by seeing every ray: a game with a real ray tracer.',
        lang: 'en',
        start_url: './',
        scope: './',
        display: 'standalone',
        background_color: '#1b2330',
        theme_color: '#1b2330',
        icons: [
          { src: 'icons/icon-192.png', sizes: '192x192', type: 'image/png' },
          { src: 'icons/icon-512.png', sizes: '512x512', type: 'image/png' },
          { src: 'icons/icon-512.png', sizes: '512x512', type: 'image/png', purpose: 'maskable' },
        ],
      },
      workbox: {
        // The models (.obj) are the levels' meshes: without them a level cannot be played offline.
        globPatterns: ['**/*.{js,css,html,svg,png,obj,webmanifest}'],
        maximumFileSizeToCacheInBytes: 4 * 1024 * 1024,
        navigateFallback: 'index.html',
        cleanupOutdatedCaches: true,
        // The first visit is the one that must work offline later: take control at once.
        clientsClaim: true,
        // A new build waits until no tab of the old one is open: activating it at once
        // deleted the old build's files under open tabs, whose teacher pages and panels
        // could then never load (issue 38). Until then both builds' files are kept.
        // docs/offline.md says what a teacher sees.
        skipWaiting: false,
      },
    }),
  ],
  test: {
    include: ['tests/**/*.test.ts'],
    // Component tests run in Chromium: vitest.browser.config.ts.
    exclude: [...configDefaults.exclude, 'tests/components/**'],
    environment: 'node',
    testTimeout: 30_000,
  },
});
