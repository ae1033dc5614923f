#include "marbler/gl/Meshes.h"

#include "MeshFileCheck.h"
#include "marbler/Error.h"
#include "marbler/OneLine.h"

#include <assimp/BaseImporter.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <sstream>

namespace marbler::gl {

MeshData loadMesh(const std::string& file) {
    try {
        detail::checkMeshFile(file);
    } catch (const InputError& e) {
        throw InputError(file + ": cannot load mesh: " + e.what());
    }
    Assimp::Importer importer;
    // Only the importers of the allowed formats stay, so a file is never handed to another one
    // (assimp tries every importer when the one its name suggests refuses it). Unregistered
    // importers are no longer the Importer's to delete.
    for (std::size_t i = importer.GetImporterCount(); i-- > 0;) {
        std::istringstream extensions(importer.GetImporterInfo(i)->mFileExtensions);
        bool allowed = false;
        for (std::string ext; extensions >> ext;)
            allowed = allowed || detail::isAllowedImporterExtension(ext);
        if (allowed) continue;
        Assimp::BaseImporter* other = importer.GetImporter(i);
        if (importer.UnregisterLoader(other) == aiReturn_SUCCESS) delete other;
    }
    // Read, then checked by Marbler before any of assimp's processing steps: a face naming a
    // vertex past the last (a damaged PLY) would reach the triangulation's assertion, which
    // aborts the whole process.
    const aiScene* scene = importer.ReadFile(file, aiProcess_ValidateDataStructure);
    if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
        throw InputError(file + ": cannot load mesh: " + oneLine(importer.GetErrorString()));
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* in = scene->mMeshes[m];
        for (unsigned f = 0; f < in->mNumFaces; ++f) {
            const aiFace& face = in->mFaces[f];
            if (face.mNumIndices == 0 || !face.mIndices)
                throw InputError(file + ": cannot load mesh: face " + std::to_string(f + 1) +
                                 " has no vertices");
            for (unsigned k = 0; k < face.mNumIndices; ++k)
                if (face.mIndices[k] >= in->mNumVertices)
                    throw InputError(file + ": cannot load mesh: face " + std::to_string(f + 1) +
                                     " names vertex " + std::to_string(face.mIndices[k] + 1) + " of " +
                                     std::to_string(in->mNumVertices));
        }
    }
    scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                                         aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                                         aiProcess_SortByPType);
    if (!scene) throw InputError(file + ": cannot load mesh: " + oneLine(importer.GetErrorString()));
    MeshData mesh;
    // Texture coordinates only when every mesh has them: a mix would leave some faces without.
    bool everyMeshHasUvs = true;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m)
        if ((scene->mMeshes[m]->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) &&
            !scene->mMeshes[m]->HasTextureCoords(0))
            everyMeshHasUvs = false;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* in = scene->mMeshes[m];
        if (!(in->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        auto base = std::uint32_t(mesh.positions.size());
        for (unsigned v = 0; v < in->mNumVertices; ++v) {
            const aiVector3D& p = in->mVertices[v];
            mesh.positions.emplace_back(p.x, p.y, p.z);
            aiVector3D n = in->mNormals ? in->mNormals[v] : aiVector3D(0, 1, 0);
            mesh.normals.emplace_back(n.x, n.y, n.z);
            if (everyMeshHasUvs) {
                // assimp counts v upwards (OpenGL); MeshData counts it down from the top row.
                const aiVector3D& t = in->mTextureCoords[0][v];
                mesh.uvs.emplace_back(t.x, 1.0f - t.y);
            }
        }
        for (unsigned f = 0; f < in->mNumFaces; ++f) {
            const aiFace& face = in->mFaces[f];
            if (face.mNumIndices != 3) continue;
            for (unsigned k = 0; k < 3; ++k)
                mesh.indices.push_back(base + face.mIndices[k]);
        }
    }
    if (mesh.indices.empty()) throw InputError(file + ": cannot load mesh: no triangles in the file");
    return mesh;
}

MeshData meshByNameOrFile(const std::string& nameOrFile) {
    for (const std::string& name : builtinMeshNames())
        if (name == nameOrFile) return builtinMesh(name);
    return loadMesh(nameOrFile);
}

} // namespace marbler::gl
