// Runs the Khronos glTF-Validator (npm gltf-validator) over the files named on the command line
// and prints one line per file: NAME, a tab, the number of errors, a tab, the error codes with
// their JSON pointers. `--check` only loads the module (exit 0 when it is installed). The module
// is looked up as node resolves it, then in npm's global folder (third_party/install-deps.sh).
'use strict';
const fs = require('fs');
const path = require('path');
const { execSync } = require('child_process');

function load_validator() {
  try {
    return require('gltf-validator');
  } catch (e) {
    const global_root = execSync('npm root -g', { stdio: ['ignore', 'pipe', 'ignore'] })
      .toString().trim();
    return require(path.join(global_root, 'gltf-validator'));
  }
}

async function main() {
  const validator = load_validator();
  const args = process.argv.slice(2);
  if (args[0] === '--check') return;
  for (const file of args) {
    const folder = path.dirname(file);
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
      uri: path.basename(file),
      maxIssues: 0,
      externalResourceFunction: (uri) => new Promise((resolve, reject) => {
        try {
          resolve(new Uint8Array(fs.readFileSync(path.join(folder, decodeURIComponent(uri)))));
        } catch (e) {
          reject(e.toString());
        }
      }),
    });
    const errors = report.issues.messages.filter((m) => m.severity === 0);
    console.log(path.basename(file) + '\t' + errors.length + '\t' +
                errors.map((m) => m.code + '@' + (m.pointer || m.offset)).join(' '));
  }
}

main().catch((e) => {
  console.error('validate_gltf: ' + e);
  process.exit(1);
});
