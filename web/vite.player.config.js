// The animation player that `tandem export --html` inlines into its pages: one script (an IIFE with
// three.js in it), dist/player/player.js, built after the viewer (whose build empties dist/).
import { defineConfig } from 'vite';

export default defineConfig({
  build: {
    outDir: 'dist/player',
    emptyOutDir: true,
    copyPublicDir: false,
    lib: {
      entry: 'src/player/player.js',
      formats: ['iife'],
      name: 'tandemPlayerBundle',
      fileName: () => 'player.js',
    },
  },
});
