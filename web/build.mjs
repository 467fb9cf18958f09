// Bundles the page (src/main.js + vtk.js) into one minified raylab-web.js and raylab-web.css
// with esbuild. Usage: node build.mjs OUTDIR   (CMake's raylab_web_bundle runs it).
// The bundle must load from file:// with no network, so nothing is left external and
// anything that would fetch a URL at run time fails the build instead.
import { build } from 'esbuild';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { readFileSync } from 'node:fs';

const here = dirname(fileURLToPath(import.meta.url));
const outdir = process.argv[2];
if (!outdir) {
  console.error('usage: node build.mjs OUTDIR');
  process.exit(2);
}

const result = await build({
  entryPoints: { 'raylab-web': join(here, 'src', 'main.js') },
  outdir,
  bundle: true,
  minify: true,
  format: 'iife',
  target: ['es2020'],
  legalComments: 'none',
  metafile: true,
  logLevel: 'warning',
  // vtk.js imports a few shader sources as text; everything else is JavaScript.
  loader: { '.glsl': 'text', '.svg': 'text' },
  define: { 'process.env.NODE_ENV': '"production"' },
});

for (const name of ['raylab-web.js', 'raylab-web.css']) {
  const text = readFileSync(join(outdir, name), 'utf8');
  const url = text.match(/\b(?:src|href)\s*=\s*["']https?:\/\/|url\(\s*["']?https?:\/\//);
  if (url) {
    console.error(`${name}: the bundle refers to an external URL (${url[0]}); it must work offline`);
    process.exit(1);
  }
}
const sizes = Object.entries(result.metafile.outputs).map(([f, o]) => `${f} ${o.bytes} bytes`);
console.log(`raylab-web bundle: ${sizes.join(', ')}`);
