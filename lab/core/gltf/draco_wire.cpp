// draco_wire.cpp — a Draco result as one array of bytes, and back (draco_mesh.h).
//
// Layout, little-endian 32-bit words: 0 = failure, then the length and bytes of `where` and of
// `message`; 1 = a mesh, then points, faces, whether positions and normals follow, the positions
// (points × 3 floats) and normals when they do, and the indices (faces × 3).
#include "core/gltf/draco_mesh.h"

#include <cmath>
#include <cstring>

namespace lab::gltf_detail {

namespace {

void put(std::vector<unsigned char>& out, std::uint32_t word) {
    for (int i = 0; i < 4; ++i) {
        out.push_back(static_cast<unsigned char>(word >> (8 * i)));
    }
}

void putBytes(std::vector<unsigned char>& out, const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    out.insert(out.end(), bytes, bytes + size);
}

void putText(std::vector<unsigned char>& out, const std::string& text) {
    put(out, static_cast<std::uint32_t>(text.size()));
    putBytes(out, text.data(), text.size());
}

// Reads from the front of [at, end), refusing to read past it.
struct Reader {
    const unsigned char* at;
    const unsigned char* end;
    bool ok = true;

    std::uint32_t word() {
        if (end - at < 4) {
            ok = false;
            return 0;
        }
        std::uint32_t w = 0;
        for (int i = 0; i < 4; ++i) {
            w |= static_cast<std::uint32_t>(at[i]) << (8 * i);
        }
        at += 4;
        return w;
    }
    bool bytes(void* into, std::uint64_t size) {
        if (!ok || static_cast<std::uint64_t>(end - at) < size) {
            return ok = false;
        }
        std::memcpy(into, at, static_cast<std::size_t>(size));
        at += size;
        return true;
    }
    std::string text() {
        const std::uint32_t size = word();
        if (!ok || static_cast<std::uint64_t>(end - at) < size) {
            ok = false;
            return {};
        }
        std::string t(reinterpret_cast<const char*>(at), size);
        at += size;
        return t;
    }
};

} // namespace

std::vector<unsigned char> packDracoResult(const DracoResult& result) {
    std::vector<unsigned char> out;
    if (const auto* failure = std::get_if<DracoFailure>(&result)) {
        put(out, 0);
        putText(out, failure->where);
        putText(out, failure->message);
        return out;
    }
    const DracoMesh& mesh = std::get<DracoMesh>(result);
    out.reserve(24 + 4 * (mesh.positions.size() + mesh.normals.size() + mesh.indices.size()));
    put(out, 1);
    put(out, mesh.points);
    put(out, mesh.faces);
    put(out, mesh.positions.empty() ? 0 : 1);
    put(out, mesh.normals.empty() ? 0 : 1);
    putBytes(out, mesh.positions.data(), mesh.positions.size() * 4);
    putBytes(out, mesh.normals.data(), mesh.normals.size() * 4);
    putBytes(out, mesh.indices.data(), mesh.indices.size() * 4);
    return out;
}

std::optional<DracoResult> unpackDracoResult(const unsigned char* data, std::size_t size) {
    Reader in{data, data + size};
    const std::uint32_t kind = in.word();
    if (in.ok && kind == 0) {
        DracoFailure failure;
        failure.where = in.text();
        failure.message = in.text();
        return in.ok && in.at == in.end ? std::optional<DracoResult>(failure) : std::nullopt;
    }
    DracoMesh mesh;
    mesh.points = in.word();
    mesh.faces = in.word();
    const std::uint32_t positions = in.word(), normals = in.word();
    if (!in.ok || kind != 1 || positions > 1 || normals > 1 || mesh.points == 0 || mesh.faces == 0 ||
        std::uint64_t(mesh.points) * (positions + normals) * 12 + std::uint64_t(mesh.faces) * 12 !=
            static_cast<std::uint64_t>(in.end - in.at)) {
        return std::nullopt;
    }
    mesh.positions.resize(positions ? std::size_t(mesh.points) * 3 : 0);
    mesh.normals.resize(normals ? std::size_t(mesh.points) * 3 : 0);
    mesh.indices.resize(std::size_t(mesh.faces) * 3);
    in.bytes(mesh.positions.data(), mesh.positions.size() * 4);
    in.bytes(mesh.normals.data(), mesh.normals.size() * 4);
    in.bytes(mesh.indices.data(), mesh.indices.size() * 4);
    for (std::uint32_t v : mesh.indices) {
        if (v >= mesh.points) {
            return std::nullopt;
        }
    }
    return in.ok ? std::optional<DracoResult>(std::move(mesh)) : std::nullopt;
}

DracoQueryWords queryWords(const DracoQuery& q) {
    return {{q.position.listed ? 1.0 : 0.0, static_cast<double>(q.position.id), q.position.used ? 1.0 : 0.0,
             q.normal.listed ? 1.0 : 0.0, static_cast<double>(q.normal.id), q.normal.used ? 1.0 : 0.0,
             static_cast<double>(q.maxPoints), static_cast<double>(q.maxFaces)}};
}

DracoQuery queryFromWords(const double* w, double maxBytes) {
    // Whole numbers below 2^53 on the way in, so each double holds its value exactly.
    auto whole = [](double v) { return std::isfinite(v) && v >= 0 ? static_cast<std::uint64_t>(v) : 0; };
    auto id = [](double v) { return std::isfinite(v) && v >= 0 && v <= 0xFFFFFFFF ? static_cast<std::int64_t>(v) : -1; };
    DracoQuery q;
    q.position = {w[0] != 0, id(w[1]), w[2] != 0};
    q.normal = {w[3] != 0, id(w[4]), w[5] != 0};
    q.maxPoints = whole(w[6]);
    q.maxFaces = whole(w[7]);
    q.maxBytes = whole(maxBytes);
    return q;
}

} // namespace lab::gltf_detail
