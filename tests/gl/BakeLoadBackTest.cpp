// Baked objects read back by assimp, the library most 3D tools' importers resemble: the OBJ, the
// glTF and the GLB keep the mesh and name their texture, and baking an object by its own texture
// coordinates, read from a file, reproduces the texture they were made with (so the v axis runs
// the same way in the writers and the reader). No GL context is needed.

#include "RenderTestUtil.h"
#include "TestUtil.h"
#include "marbler/Bake.h"
#include "marbler/GenomeIO.h"
#include "marbler/gl/Meshes.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <set>

namespace marbler {
namespace {

Genome slateBlock() {
    return loadGenome(test::dataDir() / "examples" / "slate-block.marble.json");
}

struct Baked {
    MeshData mesh;
    Image texture;
};

Baked bake(const Genome& genome, const MeshData& mesh, int n) {
    BakeSettings settings;
    settings.textureSize = n;
    settings.aa = "none";
    return {mesh, bakeTexture(genome, mesh, settings).image};
}

TEST(BakeLoadBack, AssimpReadsEveryFormatWithItsTexture) {
    const auto dir = test::outputDir("bake-load-back");
    const Baked baked = bake(slateBlock(), withGeneratedUvs(gl::builtinMesh("cube"), 256), 256);
    for (const char* name : {"cube.obj", "cube.gltf", "cube.glb"}) {
        SCOPED_TRACE(name);
        writeTexturedMesh(baked.mesh, baked.texture, dir / name, "Slate cube");
        Assimp::Importer importer;
        const aiScene* scene =
            importer.ReadFile((dir / name).string(), aiProcess_Triangulate | aiProcess_ValidateDataStructure);
        ASSERT_TRUE(scene && !(scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) << importer.GetErrorString();
        ASSERT_GE(scene->mNumMeshes, 1u);
        const aiMesh* mesh = scene->mMeshes[0];
        EXPECT_EQ(mesh->mNumFaces, baked.mesh.indices.size() / 3);
        ASSERT_TRUE(mesh->HasTextureCoords(0));
        const aiMaterial* material = scene->mMaterials[mesh->mMaterialIndex];
        aiString texture;
        const bool hasTexture = material->GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS ||
                                material->GetTexture(aiTextureType_BASE_COLOR, 0, &texture) == AI_SUCCESS;
        ASSERT_TRUE(hasTexture);
        if (std::string(name) == "cube.glb") {
            // Embedded: assimp names it "*0" and holds the PNG.
            ASSERT_EQ(scene->mNumTextures, 1u);
            EXPECT_EQ(std::string(texture.C_Str()), "*0");
            EXPECT_EQ(std::string(scene->mTextures[0]->achFormatHint), "png");
        } else {
            EXPECT_EQ(std::string(texture.C_Str()), "cube.png");
        }
    }
}

TEST(BakeLoadBack, OwnUvsFromAFileGiveTheSameTexture) {
    // Bake the vase with generated UVs and write it as OBJ; read that file back (its UVs through
    // OBJ's upward v and assimp) and bake again by them: the same texels hold the same colours.
    const auto dir = test::outputDir("bake-own-uvs");
    const Genome genome = slateBlock();
    const int n = 1024;
    const Baked first = bake(genome, withGeneratedUvs(gl::builtinMesh("vase"), n), n);
    writeTexturedMesh(first.mesh, first.texture, dir / "vase.obj");
    const MeshData loaded = gl::loadMesh((dir / "vase.obj").string());
    ASSERT_TRUE(hasUsableUvs(loaded));
    const Baked second = bake(genome, loaded, n);
    const test::ImageDiff diff = test::compareImages(first.texture, second.texture, 0);
    EXPECT_GT(diff.shareWithin, 0.995) << "a flipped or shifted v axis would move every triangle";
    EXPECT_EQ(test::readImage8(dir / "vase.png").rgb, first.texture.rgb);
}

TEST(BakeLoadBack, EveryBuiltInObjectKeepsItsOwnUvsInTheFile) {
    // Baked at 256 by its own texture coordinates (issue 23), each object's GLB read back by
    // assimp has those coordinates (the same set, v counted upwards there) and its texture shows
    // the design.
    const auto dir = test::outputDir("bake-own-uvs-load-back");
    for (const std::string& name : builtinMeshNames()) {
        SCOPED_TRACE(name);
        const MeshData mesh = gl::builtinMesh(name);
        ASSERT_TRUE(hasUsableUvs(mesh));
        const Baked baked = bake(slateBlock(), mesh, 256);
        writeTexturedMesh(baked.mesh, baked.texture, dir / (name + ".glb"));
        Assimp::Importer importer;
        const aiScene* scene = importer.ReadFile((dir / (name + ".glb")).string(), aiProcess_Triangulate);
        ASSERT_TRUE(scene && !(scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) << importer.GetErrorString();
        ASSERT_EQ(scene->mNumMeshes, 1u);
        const aiMesh* in = scene->mMeshes[0];
        ASSERT_TRUE(in->HasTextureCoords(0));
        ASSERT_EQ(in->mNumVertices, mesh.uvs.size());
        std::vector<std::pair<float, float>> read, made;
        for (unsigned v = 0; v < in->mNumVertices; ++v)
            read.emplace_back(in->mTextureCoords[0][v].x, 1.0f - in->mTextureCoords[0][v].y);
        for (const glm::vec2& uv : mesh.uvs)
            made.emplace_back(uv.x, uv.y);
        std::sort(read.begin(), read.end());
        std::sort(made.begin(), made.end());
        int differing = 0;
        for (std::size_t k = 0; k < made.size(); ++k)
            differing += std::abs(read[k].first - made[k].first) > 1e-6f ||
                         std::abs(read[k].second - made[k].second) > 1e-6f;
        EXPECT_EQ(differing, 0);

        // The texture inside the GLB is the baked one, and shows more than one colour.
        ASSERT_EQ(scene->mNumTextures, 1u);
        const aiTexture* texture = scene->mTextures[0];
        ASSERT_EQ(texture->mHeight, 0u) << "a compressed (PNG) texture";
        const std::filesystem::path png = dir / (name + "-inside.png");
        {
            std::ofstream out(png, std::ios::binary);
            out.write(reinterpret_cast<const char*>(texture->pcData), std::streamsize(texture->mWidth));
        }
        const Image inside = test::readImage8(png);
        EXPECT_EQ(inside.rgb, baked.texture.rgb);
        std::set<std::array<std::uint8_t, 3>> colours;
        for (std::size_t k = 0; k + 2 < inside.rgb.size(); k += 3)
            colours.insert({inside.rgb[k], inside.rgb[k + 1], inside.rgb[k + 2]});
        EXPECT_GT(colours.size(), 3u);
    }
}

} // namespace
} // namespace marbler
