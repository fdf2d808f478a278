// Runs the Khronos glTF validator (npm gltf-validator, installed by the test fixture into the build
// tree) on each file given; prints every error and exits 1 if any file has one.
// usage: node gltf_validate.js VALIDATOR_PREFIX FILE.glb|FILE.gltf...
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require(path.join(path.resolve(process.argv[2]), 'node_modules', 'gltf-validator'));

async function validate(file) {
    const folder = path.dirname(file);
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
        uri: path.basename(file),
        externalResourceFunction: (uri) =>
            new Promise((resolve, reject) => {
                fs.readFile(path.join(folder, decodeURIComponent(uri)), (error, data) =>
                    error ? reject(error.toString()) : resolve(new Uint8Array(data)));
            }),
    });
    const errors = report.issues.messages.filter((m) => m.severity === 0);
    for (const m of errors) console.log(`${file}: ${m.code} at ${m.pointer}: ${m.message}`);
    console.log(`${file}: ${report.issues.numErrors} errors, ${report.issues.numWarnings} warnings, ${report.issues.numInfos} infos`);
    return errors.length === 0 && report.issues.numErrors === 0;
}

(async () => {
    const files = process.argv.slice(3);
    if (files.length === 0) throw new Error('no files to validate');
    let ok = true;
    for (const file of files) ok = (await validate(file)) && ok;
    process.exit(ok ? 0 : 1);
})().catch((error) => {
    console.log(String(error));
    process.exit(1);
});
