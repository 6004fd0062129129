// Validates a .glb with the Khronos glTF validator (npm gltf-validator, tests/tools/package.json) and
// prints its report's issue counts and info as one JSON line; exit 0 when it ran (whatever it found),
// 2 when the file cannot be read or the validator failed. Usage: node validate_gltf.js FILE
'use strict';
const fs = require('fs');
const validator = require('gltf-validator');

const file = process.argv[2];
let bytes;
try {
  bytes = new Uint8Array(fs.readFileSync(file));
} catch (e) {
  console.error(`cannot read ${file}: ${e.message}`);
  process.exit(2);
}
validator.validateBytes(bytes, { maxIssues: 20 }).then((report) => {
  const first = report.issues.messages.slice(0, 5).map((m) => `${m.code}: ${m.message} (${m.pointer || ''})`);
  console.log(JSON.stringify({
    errors: report.issues.numErrors,
    warnings: report.issues.numWarnings,
    infos: report.issues.numInfos,
    draw_calls: report.info ? report.info.drawCallCount : null,  // one per primitive
    materials: report.info ? report.info.materialCount : null,
    triangles: report.info ? report.info.totalTriangleCount : null,
    first,
  }));
}).catch((e) => {
  console.error(`validator failed: ${e}`);
  process.exit(2);
});
