# Issue 29 (Products): Bake onto object for flat and solid designs, from the large view and the
# editor, onto the object shown, a built-in or a mesh file: (English, Turkish, German).
WORDS = [
("&Bake onto object", "Nesneye &pişir", "Auf Objekt &backen"),
("Write the object with the design baked into its texture, following the object's texture coordinates, for other 3D tools (glTF .glb or .gltf, OBJ; a %1 × %1 texture)", "Deseni nesnenin doku koordinatlarını izleyerek dokusuna pişirilmiş nesneyi başka 3B araçlar için yaz (glTF .glb veya .gltf, OBJ; %1 × %1 doku)", "Das Objekt mit dem entlang seiner Texturkoordinaten in seine Textur gebackenen Muster für andere 3D-Werkzeuge schreiben (glTF .glb oder .gltf, OBJ; eine %1 × %1-Textur)"),
("The object shown (%1)…", "Gösterilen nesne (%1)…", "Das gezeigte Objekt (%1)…"),
("&Mesh file…", "&Ağ dosyası…", "&Mesh-Datei…"),
("Baked onto %1", "Nesneye pişirildi: %1", "Auf das Objekt gebacken: %1"),
]
