// The browser session's HTTP server on 127.0.0.1: the npm packages and this folder (any regular file
// inside each), and from the untrusted scene's folder only the files its glTF names (the scene
// file, its buffers' and images' relative URIs). Paths are taken apart by components, never
// decoded whole, so no escape can make a separator or a climb.
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';

const types = { '.js': 'text/javascript', '.mjs': 'text/javascript', '.html': 'text/html', '.json': 'application/json',
                '.gltf': 'model/gltf+json', '.glb': 'model/gltf-binary', '.bin': 'application/octet-stream',
                '.png': 'image/png', '.jpg': 'image/jpeg', '.jpeg': 'image/jpeg', '.ktx2': 'image/ktx2',
                '.webp': 'image/webp', '.wasm': 'application/wasm' };
const maxJsonBytes = 64 * 1024 * 1024; // a glTF's JSON past this is refused unread
const glbMagic = 0x46546c67, glbJsonChunk = 0x4e4f534a; // 'glTF', 'JSON' (little-endian)

// A '/'-separated raw path as its components, each percent-decoded on its own; null when an
// escape is malformed. Nothing is judged here.
function decodeComponents(raw) {
    const out = [];
    for (const part of raw.split('/')) {
        try { out.push(decodeURIComponent(part)); } catch { return null; }
    }
    return out;
}

// One plain name: not empty, not a climb or a self-reference, no separator or NUL once decoded.
const plainName = (n) => n !== '' && n !== '.' && n !== '..' && !/[/\\\0]/.test(n);

// A request's path ('/root/a/b', raw, query cut) as decoded components; null unless every one is plain.
export function requestComponents(rawUrl) {
    const pathname = String(rawUrl).split(/[?#]/)[0];
    if (!pathname.startsWith('/')) return null;
    const parts = decodeComponents(pathname.slice(1));
    return parts && parts.every(plainName) ? parts : null;
}

// A glTF URI as an allowlist key ('a/b c.png'): a relative reference with no scheme and no leading
// '/', decoded per component, '.' components dropped as the browser drops them; null otherwise
// (data:, http:, file:, '//host', a '..' anywhere, a malformed escape, and '?', '#', '+' or a
// control character, which the browser, tinygltf and ssaolab's own check would each read differently:
// scene/load/browser_assets.cpp refuses the same).
export function uriKey(uri) {
    if (typeof uri !== 'string' || /^[a-z][a-z0-9+.-]*:/i.test(uri) || /^[/\\]/.test(uri)) return null;
    if (/[?#+\x00-\x1f\x7f]/.test(uri)) return null;
    const parts = decodeComponents(uri);
    const kept = parts && parts.filter((n) => n !== '.');
    return kept && kept.length > 0 && kept.every(plainName) ? kept.join('/') : null;
}

// The glTF's JSON, .gltf or .glb told apart by the magic as GLTFLoader does; bounded in size.
function readGltfJson(file) {
    const fd = fs.openSync(file, 'r');
    try {
        const size = fs.fstatSync(fd).size;
        const head = Buffer.alloc(20);
        const got = fs.readSync(fd, head, 0, 20, 0);
        let start = 0, length = size;
        if (got >= 4 && head.readUInt32LE(0) === glbMagic) {
            if (got < 20 || head.readUInt32LE(4) !== 2 || head.readUInt32LE(16) !== glbJsonChunk)
                throw new Error(`${path.basename(file)}: not a glTF 2.0 binary with a JSON chunk first`);
            start = 20;
            length = head.readUInt32LE(12);
            if (start + length > size) throw new Error(`${path.basename(file)}: the JSON chunk runs past the file`);
        }
        if (length > maxJsonBytes) throw new Error(`${path.basename(file)}: its JSON is over ${maxJsonBytes >> 20} MiB`);
        const text = Buffer.alloc(length);
        if (fs.readSync(fd, text, 0, length, start) !== length) throw new Error(`${path.basename(file)}: short read`);
        return JSON.parse(text.toString('utf8').replace(/^\uFEFF/, ''));
    } finally {
        fs.closeSync(fd);
    }
}

// What the scene root may serve: the scene file's name and the keys of its buffers' and images'
// relative URIs (the only files GLTFLoader asks for). Hostile URIs simply never get a key.
export function sceneAllowlist(sceneFile) {
    const json = readGltfJson(sceneFile);
    const allowed = new Set([path.basename(sceneFile)]);
    for (const list of [json?.buffers, json?.images]) {
        if (!Array.isArray(list)) continue;
        for (const item of list) {
            const key = uriKey(item?.uri);
            if (key !== null) allowed.add(key);
        }
    }
    return allowed;
}

// Whether `file` lies below `base` (both real paths): by path.relative, never by string prefix.
function inside(base, file) {
    const r = path.relative(base, file);
    return r !== '' && r !== '..' && !r.startsWith(`..${path.sep}`) && !path.isAbsolute(r);
}

// An open fd on the scene root's file, or null: no link at any step (lstat each component), a
// regular file at the end (O_NOFOLLOW and O_NONBLOCK so a link or a FIFO can't slip in or hang).
function openSceneFile(root, parts) {
    let p = root;
    for (let i = 0; i < parts.length; ++i) {
        p = path.join(p, parts[i]);
        const st = fs.lstatSync(p);
        if (i < parts.length - 1 ? !st.isDirectory() : !st.isFile()) return null;
    }
    return fs.openSync(p, fs.constants.O_RDONLY | fs.constants.O_NOFOLLOW | fs.constants.O_NONBLOCK);
}

// An open fd on a module root's file, or null: its real path must stay inside the root's real path.
function openModuleFile(realBase, parts) {
    const real = fs.realpathSync(path.join(realBase, ...parts));
    if (!inside(realBase, real) || !fs.statSync(real).isFile()) return null;
    return fs.openSync(real, fs.constants.O_RDONLY | fs.constants.O_NONBLOCK);
}

// One request: an fd for it, or null (404). Throws on anything odd, which is a 404 too.
function openFor(req, bases, scene) {
    if (req.method !== 'GET' && req.method !== 'HEAD') return null;
    const parts = requestComponents(req.url);
    if (!parts || parts.length < 2) return null;
    const [root, ...rest] = parts;
    if (root === 'scene') return scene.allowed.has(rest.join('/')) ? openSceneFile(scene.root, rest) : null;
    return Object.hasOwn(bases, root) ? openModuleFile(bases[root], rest) : null;
}

function serve(req, res, bases, scene) {
    let fd = null;
    try {
        if (req.url === '/favicon.ico') { res.writeHead(204); res.end(); return; }
        fd = openFor(req, bases, scene);
        const st = fd === null ? null : fs.fstatSync(fd);
        if (!st?.isFile()) throw new Error('not a regular file');
        const ext = path.extname(req.url.split(/[?#]/)[0]).toLowerCase();
        res.writeHead(200, { 'content-type': types[ext] ?? 'application/octet-stream', 'content-length': st.size });
        if (req.method === 'HEAD') { fs.closeSync(fd); fd = null; res.end(); return; }
        const stream = fs.createReadStream(null, { fd, autoClose: true });
        fd = null; // the stream closes it now
        stream.on('error', () => res.destroy());
        stream.pipe(res);
    } catch {
        if (fd !== null) fs.closeSync(fd);
        if (!res.headersSent) { res.writeHead(404); res.end(); } else res.destroy();
    }
}

// Starts the server. roots: { name: folder } served whole (by real path); sceneFile: the glTF, whose
// folder is served as /scene/ by its allowlist. Returns { port, sceneUrl (the page's URL of the
// scene), allowed (the allowlist), close() }. Throws when the glTF's JSON can't be read.
export async function startServer({ roots, sceneFile }) {
    const realScene = fs.realpathSync(sceneFile); // the name the user gave, a link or not, is trusted
    const scene = { root: path.dirname(realScene), allowed: sceneAllowlist(realScene) };
    const bases = {};
    for (const [name, dir] of Object.entries(roots)) {
        try { if (name !== 'scene') bases[name] = fs.realpathSync(dir); } catch { /* absent package: its URLs 404 */ }
    }
    const server = http.createServer((req, res) => serve(req, res, bases, scene));
    server.on('clientError', (_, socket) => socket.destroy());
    await new Promise((resolve, reject) => { server.once('error', reject); server.listen(0, '127.0.0.1', resolve); });
    return { port: server.address().port, sceneUrl: `/scene/${encodeURIComponent(path.basename(realScene))}`,
             allowed: scene.allowed, close: () => new Promise((r) => server.close(r)) };
}
