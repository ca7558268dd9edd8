// The binary glTF container (glTF 2.0 section 4.4): a 12-byte header, a JSON chunk padded with spaces and an
// optional BIN chunk padded with zeros, both to 4 bytes.
import fs from "node:fs";

const MAGIC = 0x46546c67, JSON_CHUNK = 0x4e4f534a, BIN_CHUNK = 0x004e4942;

function padded(data, byte) { return Buffer.concat([data, Buffer.alloc((4 - (data.length % 4)) % 4, byte)]); }

export function encodeGlb(json, bin) {
    const chunks = [[JSON_CHUNK, padded(Buffer.from(JSON.stringify(json)), 0x20)]];
    if (bin)
        chunks.push([BIN_CHUNK, padded(bin, 0)]);
    const parts = [Buffer.alloc(12)];
    for (const [type, data] of chunks) {
        const head = Buffer.alloc(8);
        head.writeUInt32LE(data.length, 0);
        head.writeUInt32LE(type, 4);
        parts.push(head, data);
    }
    const out = Buffer.concat(parts);
    out.writeUInt32LE(MAGIC, 0);
    out.writeUInt32LE(2, 4);
    out.writeUInt32LE(out.length, 8);
    return out;
}

// The JSON and the BIN chunk (null when there is none) of a .glb, or a .gltf's JSON.
export function readGltf(file) {
    const bytes = fs.readFileSync(file);
    if (bytes.readUInt32LE(0) !== MAGIC)
        return { json: JSON.parse(bytes.toString("utf8")), bin: null };
    const jsonLength = bytes.readUInt32LE(12);
    const json = JSON.parse(bytes.subarray(20, 20 + jsonLength).toString("utf8"));
    const binStart = 20 + jsonLength;
    const bin = binStart < bytes.length ? bytes.subarray(binStart + 8, binStart + 8 + bytes.readUInt32LE(binStart)) : null;
    return { json, bin };
}
