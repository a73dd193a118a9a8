// One web engine's AO at many parameter sets, over several views of one scene, in one browser
// session (session.mjs, peers.js runEngine): what `ssaolab tune --engine` asks for each step of
// its search, then scores in-process against its reference.
//
// node run_engine.mjs --modules DIR --jobs FILE --out DIR
// FILE: { scene (.gltf/.glb), width, height, page (peers.html, the default, or babylon.html: every
//         engine of one session runs on one page), peer (the page's name), params (rows of the engine's
//         table), views: [{ camera (metrics.json's), radius (R, scene units) }], frames,
//         jobs: [{ view, values: { name: value }, scale: { name: factor } (optional), image (file name),
//                  frames (optional), peer (optional: another engine, whose rows are tables[peer]) }],
//         tables: { peer: params } (optional: the rows of each other engine the jobs name) }
// Writes each job's AO as DIR/IMAGE (binary PGM, top row first) and DIR/results.json:
// { renderer, three_revision, jobs: [{ image, values (what the pass ran with), frame_ms, plain_ms, ao_ms,
//   ao_ms_min, ao_ms_max }] }; each job's entry also as DIR/jN.json once it is done, and when the page
// hangs on job N past the browser's time limit, DIR/hung.json { job: N } before it stops (the caller
// keeps what was done and runs the rest anew: engine_runner.cpp).
import fs from 'node:fs';
import path from 'node:path';
import { openSession, parseArgs, pgmBytes } from './session.mjs';

const args = parseArgs(process.argv, ['modules', 'jobs', 'out'], 'run_engine');
const spec = JSON.parse(fs.readFileSync(args.jobs, 'utf8'));
const { width, height } = spec;
let session, current = -1;
const onLate = () => { if (current >= 0) fs.writeFileSync(path.join(args.out, 'hung.json'), JSON.stringify({ job: current })); };
try {
    fs.mkdirSync(args.out, { recursive: true });
    session = await openSession({ modules: args.modules, sceneFile: spec.scene, width, height, page: spec.page,
                                  camera: spec.views[0].camera, radius: spec.views[0].radius, tool: 'run_engine', onLate });
} catch (e) {
    console.error(`run_engine: ${e.message.split('\n')[0]}`);
    process.exit(1);
}
let failed = false;
try {
    const { evaluate, setup } = session;
    const results = { renderer: setup.renderer, three_revision: setup.three, jobs: new Array(spec.jobs.length) };
    // By view, so each view's passes are built once.
    const order = spec.jobs.map((_, i) => i).sort((a, b) => spec.jobs[a].view - spec.jobs[b].view || a - b);
    for (const i of order) {
        const job = spec.jobs[i], view = spec.views[job.view];
        await evaluate(`view ${job.view}`, ([k, c, r]) => window.setEngineView(k, c, r),
                       [job.view, view.camera, view.radius]);
        const peer = job.peer ?? spec.peer, params = job.peer ? spec.tables[job.peer] : spec.params;
        current = i;
        const r = await evaluate(`job ${i}`, (j) => window.runEngine(j),
            { peer, params, values: job.values ?? {}, scale: job.scale ?? {}, frames: job.frames ?? spec.frames ?? 0 });
        fs.writeFileSync(path.join(args.out, path.basename(job.image)), pgmBytes(r.ao, width, height));
        const { ao, ...rest } = r;
        results.jobs[i] = { image: path.basename(job.image), ...rest };
        fs.writeFileSync(path.join(args.out, `j${i}.json`), JSON.stringify(results.jobs[i]));
        current = -1;
    }
    fs.writeFileSync(path.join(args.out, 'results.json'), JSON.stringify(results, null, 1));
} catch (e) {
    console.error(`run_engine: ${e.message.split('\n')[0]}`);
    failed = true;
} finally {
    await session.close();
}
process.exit(failed || session.failed() ? 1 : 0);
