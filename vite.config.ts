import { defineConfig } from 'vite';

// Vite compiles TSX natively (tsconfig: jsx react-jsx); no plugin needed.
export default defineConfig({
  server: { host: '127.0.0.1', port: 5173 },
  preview: { host: '127.0.0.1' },
  build: { target: 'es2022', chunkSizeWarningLimit: 1500 },
  // Module workers (the 3D limit-set search, src/viewport/overlay-3d/limit-set-worker.ts).
  worker: { format: 'es' },
});
