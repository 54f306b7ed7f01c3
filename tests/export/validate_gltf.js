// Runs the Khronos glTF validator on each glb named on the command line; prints a line per
// file and every error and warning, and exits 1 when any file has one (infos are allowed).
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require(path.join(__dirname, '../../tools/node/node_modules/gltf-validator'));

(async () => {
  let bad = 0;
  for (const file of process.argv.slice(2)) {
    const bytes = new Uint8Array(fs.readFileSync(file));
    const report = await validator.validateBytes(bytes, {maxIssues: 100});
    const issues = report.issues;
    console.log(`${path.basename(file)}: ${issues.numErrors} errors, ${issues.numWarnings} warnings`);
    for (const m of issues.messages)
      if (m.severity <= 1) console.log(`  ${m.severity ? 'warning' : 'error'} ${m.code} at ${m.pointer}: ${m.message}`);
    if (issues.numErrors || issues.numWarnings) ++bad;
  }
  process.exit(bad ? 1 : 0);
})().catch((e) => {
  console.error(e);
  process.exit(2);
});
