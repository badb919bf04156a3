// Build the `ws publish` viewer into the Python package data (workstation/publish/viewer/):
// viewer.js (one ES module bundling three, copc and laz-perf), laz-perf.wasm, index.html,
// viewer.css and licenses/ (the licence text of every package in the bundle). Run with
// `npm ci && node build.mjs` (the Makefile target `viewer` does both).
import { build } from 'esbuild';
import { copyFileSync, mkdirSync, readFileSync, readdirSync, renameSync, rmSync, writeFileSync, existsSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const dest = join(here, '..', 'workstation', 'publish', 'viewer');
const out = `${dest}.tmp`; // built beside, swapped in at the end: a failed build keeps the old viewer
rmSync(out, { recursive: true, force: true });
mkdirSync(join(out, 'licenses'), { recursive: true });

const result = await build({
  entryPoints: [join(here, 'src', 'viewer.js')],
  outfile: join(out, 'viewer.js'),
  bundle: true, format: 'esm', platform: 'browser', target: 'es2020', minify: true,
  legalComments: 'none', metafile: true, logLevel: 'warning',
});
copyFileSync(join(here, 'node_modules', 'laz-perf', 'lib', 'web', 'laz-perf.wasm'), join(out, 'laz-perf.wasm'));
for (const f of ['index.html', 'viewer.css']) copyFileSync(join(here, 'src', f), join(out, f));

// Every npm package with code in the bundle (plus laz-perf, whose WASM is shipped beside it).
const packages = new Set(['laz-perf']);
for (const input of Object.keys(result.metafile.inputs)) {
  const m = /node_modules\/((?:@[^/]+\/)?[^/]+)\//.exec(input);
  if (m) packages.add(m[1]);
}
const lines = ['Third-party software vendored in this viewer (bundled into viewer.js, or laz-perf.wasm):', ''];
for (const name of [...packages].sort()) {
  const dir = join(here, 'node_modules', name);
  const meta = JSON.parse(readFileSync(join(dir, 'package.json'), 'utf8'));
  const own = readdirSync(dir).find((f) => /^(licen[cs]e|copying)/i.test(f));
  const fallback = join(here, 'licenses', `${name}.txt`);
  const source = own ? join(dir, own) : existsSync(fallback) ? fallback : null;
  if (!source) throw new Error(`no licence text for ${name}: add web/licenses/${name}.txt`);
  const file = `${name.replace('/', '__')}-${meta.version}.txt`;
  copyFileSync(source, join(out, 'licenses', file));
  lines.push(`${name} ${meta.version}  ${meta.license}  ${meta.homepage || ''}  -> ${file}`);
}
writeFileSync(join(out, 'licenses', 'README.txt'), lines.join('\n') + '\n');
rmSync(dest, { recursive: true, force: true });
renameSync(out, dest);
console.log(`viewer built into ${dest}: ${[...packages].sort().join(', ')}`);
