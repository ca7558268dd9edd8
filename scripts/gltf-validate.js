#!/usr/bin/env node
// Validates glTF files with the Khronos glTF Validator (npm gltf-validator, installed globally by
// scripts/install-deps.sh) and prints one JSON verdict per file on its own line:
//   {"file": "...", "errors": [{"code": "...", "pointer": "...", "message": "..."}], "warnings": N}
// Usage: gltf-validate.js <file.gltf|file.glb>...   (external buffers and images are read beside the file)
'use strict';
const fs = require('fs');
const path = require('path');
const { execSync } = require('child_process');

function loadValidator() {
    try {
        return require('gltf-validator');
    } catch (error) {
        const root = execSync('npm root -g', { encoding: 'utf8' }).trim();
        return require(path.join(root, 'gltf-validator'));
    }
}

async function verdict(validator, file) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
        uri: path.basename(file),
        maxIssues: 0,
        externalResourceFunction: (uri) =>
            new Promise((resolve, reject) => {
                fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)), (error, data) =>
                    error ? reject(error.toString()) : resolve(new Uint8Array(data)));
            }),
    });
    const errors = report.issues.messages.filter((m) => m.severity === 0)
        .map((m) => ({ code: m.code, pointer: m.pointer || '', message: m.message }));
    return { file, errors, warnings: report.issues.numWarnings };
}

async function main() {
    const files = process.argv.slice(2);
    if (files.length === 0) {
        console.error('usage: gltf-validate.js <file.gltf|file.glb>...');
        process.exit(2);
    }
    const validator = loadValidator();
    for (const file of files) {
        try {
            console.log(JSON.stringify(await verdict(validator, file)));
        } catch (error) {
            console.log(JSON.stringify({ file, errors: [{ code: 'UNREADABLE', pointer: '', message: String(error) }],
                                         warnings: 0 }));
        }
    }
}

main();
