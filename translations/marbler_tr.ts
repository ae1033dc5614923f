<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="tr_TR">
<context>
    <name>Lineage</name>
    <message>
        <location filename="../app/shared/Lineage.cpp" line="+41"/>
        <source>(not bred)</source>
        <translation>(üretilmedi)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1, varied</source>
        <translation>%1, çeşitlenmiş</translation>
    </message>
</context>
<context>
    <name>MeshChooser</name>
    <message>
        <location filename="../app/shared/MeshChooser.cpp" line="+27"/>
        <source>Show the designs on a mesh</source>
        <translation>Desenleri bir ağ modeli üzerinde göster</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Meshes (*.obj *.stl *.ply *.gltf *.glb *.off);;All files (*)</source>
        <translation>Ağ modelleri (*.obj *.stl *.ply *.gltf *.glb *.off);;Tüm dosyalar (*)</translation>
    </message>
</context>
<context>
    <name>QMessageBox</name>
    <message>
        <location filename="../app/shared/Language.cpp" line="+48"/>
        <source>Show Details...</source>
        <translation>Ayrıntıları göster...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hide Details...</source>
        <translation>Ayrıntıları gizle...</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <location filename="../app/editor/Recovery.cpp" line="+140"/>
        <source>A recovery file was skipped: %1</source>
        <translation>Bir kurtarma dosyası atlandı: %1</translation>
    </message>
    <message>
        <location filename="../app/shared/BackgroundJob.cpp" line="+36"/>
        <source>an unknown error</source>
        <translation>bilinmeyen bir hata</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cancel</source>
        <translation>İptal</translation>
    </message>
    <message>
        <location filename="../app/shared/BakeObject.cpp" line="+28"/>
        <source>Baking %1…</source>
        <translation>%1 pişiriliyor…</translation>
    </message>
    <message>
        <location line="+30"/>
        <location line="+13"/>
        <location line="+18"/>
        <source>Cannot bake onto the object</source>
        <translation>Nesneye pişirilemiyor</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&amp;Bake onto object</source>
        <translation>Nesneye &amp;pişir</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Write the object with the design baked into its texture, following the object&apos;s texture coordinates, for other 3D tools (glTF .glb or .gltf, OBJ; a %1 × %1 texture)</source>
        <translation>Deseni nesnenin doku koordinatlarını izleyerek dokusuna pişirilmiş nesneyi başka 3B araçlar için yaz (glTF .glb veya .gltf, OBJ; %1 × %1 doku)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The object shown (%1)…</source>
        <translation>Gösterilen nesne (%1)…</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Mesh file…</source>
        <translation>&amp;Ağ dosyası…</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Bake onto object…</source>
        <translation>Nesneye &amp;pişir…</translation>
    </message>
    <message>
        <location line="-57"/>
        <source>Bake onto object</source>
        <translation>Nesneye pişir</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>3D objects (*.glb *.gltf *.obj)</source>
        <translation>3B nesneler (*.glb *.gltf *.obj)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: choose .glb, .gltf or .obj</source>
        <translation>%1: .glb, .gltf veya .obj seçin</translation>
    </message>
    <message>
        <location filename="../app/shared/DesignDialog.cpp" line="+423"/>
        <source>Save design</source>
        <translation>Deseni kaydet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Marbler genomes (*.marble.json)</source>
        <translation>Marbler genomları (*.marble.json)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cannot save the design</source>
        <translation>Desen kaydedilemiyor</translation>
    </message>
    <message>
        <location filename="../app/shared/ExportSettingsDialog.cpp" line="+49"/>
        <source>Off (1 sample, fastest)</source>
        <translation>Kapalı (1 örnek, en hızlı)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One sample a pixel: hard, stepped edges</source>
        <translation>Piksel başına bir örnek: sert, basamaklı kenarlar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Smooth (4 samples, default)</source>
        <translation>Pürüzsüz (4 örnek, varsayılan)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Four samples a pixel on a rotated grid: smooth edges at a small cost</source>
        <translation>Döndürülmüş bir ızgarada piksel başına dört örnek: az bir bedelle pürüzsüz kenarlar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Soft (5 samples)</source>
        <translation>Yumuşak (5 örnek)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Five samples a pixel, the centre weighted most: slightly soft edges</source>
        <translation>Piksel başına beş örnek, en çok merkez ağırlıklı: hafifçe yumuşak kenarlar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fine checkerboard (%1 samples)</source>
        <translation>İnce dama (%1 örnek)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Samples on every other square of a 4 × 4 grid</source>
        <translation>4 × 4 bir ızgarada bir kare atlayarak dizilen örnekler</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fine (%1 samples)</source>
        <translation>İnce (%1 örnek)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Eight samples a pixel, each in a row and a column of its own: fine edges</source>
        <translation>Piksel başına sekiz örnek, her biri kendi satırında ve kendi sütununda: ince kenarlar</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Grid %1 × %1 (%2 samples)</source>
        <translation>Izgara %1 × %1 (%2 örnek)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Samples on a regular %1 × %1 grid a pixel: finer and slower as it grows</source>
        <translation>Piksel başına düzenli bir %1 × %1 ızgarada örnekler: büyüdükçe daha ince ve daha yavaş</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Printer profile</source>
        <translation>Yazıcı profili</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ICC profiles (*.icc *.icm);;All files (*)</source>
        <translation>ICC profilleri (*.icc *.icm);;Tüm dosyalar (*)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The image would be %1 × %2 pixels: choose a size of at least 1 pixel.</source>
        <translation>Görüntü %1 × %2 piksel olurdu: en az 1 piksellik bir boyut seçin.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The image would be %L1 × %L2 pixels (%L3 megapixels); Marbler renders at most %L4 pixels a side and %L5 megapixels. Choose a smaller size or a lower resolution.</source>
        <translation>Görüntü %L1 × %L2 piksel (%L3 megapiksel) olurdu; Marbler bir kenarda en çok %L4 piksel ve %L5 megapiksel işler. Daha küçük bir boyut veya daha düşük bir çözünürlük seçin.</translation>
    </message>
    <message>
        <location filename="../app/shared/SourcePermissions.cpp" line="+23"/>
        <source>Read an image outside the design&apos;s folder?</source>
        <translation>Desenin klasörü dışındaki bir görüntü okunsun mu?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This design reads an image outside its folder: %1. Read it?</source>
        <translation>Bu desen klasörünün dışındaki bir görüntüyü okuyor: %1. Okunsun mu?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The design %1 names it. A design may read images only from its own folder unless you allow it; the answer holds until Marbler closes.</source>
        <translation>Onu %1 deseni belirtiyor. Bir desen, siz izin vermedikçe yalnızca kendi klasöründeki görüntüleri okuyabilir; yanıtınız Marbler kapanana dek geçerlidir.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Allow</source>
        <translation>İzin ver</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Don&apos;t allow</source>
        <translation>İzin verme</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>this design reads an image outside its folder (%1), which you chose not to read</source>
        <translation>bu desen klasörünün dışındaki bir görüntüyü (%1) okuyor; onu okumamayı seçtiniz</translation>
    </message>
    <message>
        <location filename="../app/workbench/WorkbenchPicture.cpp" line="+25"/>
        <source>Pictures (%1);;All files (*)</source>
        <translation>Resimler (%1);;Tüm dosyalar (*)</translation>
    </message>
    <message>
        <location filename="../app/workbench/OpenPlacement.cpp" line="+144"/>
        <source>Marble a picture?</source>
        <translation>Resim ebrulansın mı?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is a picture without a Marbler design in it.

Marble it: nine designs whose bath is the picture, as File ▸ Marble a picture makes?</source>
        <translation>%1, içinde Marbler deseni olmayan bir resim.

Ebrulansın mı? Dosya ▸ Bir resmi ebrula komutunun yaptığı gibi, teknesi bu resim olan dokuz desen yapılır.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Marble the picture</source>
        <translation>Resmi &amp;ebrula</translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <location filename="../app/shared/Language.cpp" line="-19"/>
        <source>OK</source>
        <translation>Tamam</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save</source>
        <translation>Kaydet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save All</source>
        <translation>Tümünü kaydet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open</source>
        <translation>Aç</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Yes</source>
        <translation>&amp;Evet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yes to &amp;All</source>
        <translation>&amp;Tümüne evet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;No</source>
        <translation>&amp;Hayır</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>N&amp;o to All</source>
        <translation>Tümüne h&amp;ayır</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Abort</source>
        <translation>Vazgeç</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retry</source>
        <translation>Yeniden dene</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ignore</source>
        <translation>Yok say</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation>Kapat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>İptal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Discard</source>
        <translation>Vazgeç ve at</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Help</source>
        <translation>Yardım</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply</source>
        <translation>Uygula</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset</source>
        <translation>Sıfırla</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore Defaults</source>
        <translation>Varsayılanlara dön</translation>
    </message>
</context>
<context>
    <name>Registry</name>
    <message>
        <location filename="registry-words.cpp" line="+26"/>
        <source>Centre</source>
        <translation>Merkez</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>design units</source>
        <translation>desen birimi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>centre of the tool</source>
        <translation>aracın merkezi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Origin</source>
        <translation>Başlangıç noktası</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a point on the stroke&apos;s path</source>
        <translation>çekişin yolu üzerinde bir nokta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius</source>
        <translation>Yarıçap</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>radius</source>
        <translation>yarıçap</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ink</source>
        <translation>Boya</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>palette index of the ink</source>
        <translation>boyanın paletteki sırası</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Axis</source>
        <translation>Eksen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis (turned by the right-hand rule)</source>
        <translation>eksen (sağ el kuralıyla döner)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angle</source>
        <translation>Açı</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>degrees</source>
        <translation>derece</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>direction of motion, clockwise from +x</source>
        <translation>hareket yönü, +x&apos;ten saat yönünde</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Direction</source>
        <translation>Yön</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>direction of motion</source>
        <translation>hareket yönü</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Normal</source>
        <translation>Normal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>across the plane the tine sweeps</source>
        <translation>dişin taradığı düzleme dik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shift</source>
        <translation>Kayma</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>largest shift, at the tine</source>
        <translation>en büyük kayma, dişte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sharpness</source>
        <translation>Keskinlik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sharpness: smaller concentrates the shift near the tine</source>
        <translation>keskinlik: daha küçüğü kaymayı dişin yakınında toplar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spacing</source>
        <translation>Aralık</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>distance between tines</source>
        <translation>dişler arası uzaklık</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Amplitude</source>
        <translation>Genlik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>largest shift of the wave</source>
        <translation>dalganın en büyük kayması</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wavelength</source>
        <translation>Dalga boyu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>length of one period</source>
        <translation>bir periyodun uzunluğu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Phase</source>
        <translation>Faz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>phase of the wave</source>
        <translation>dalganın fazı</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shape</source>
        <translation>Biçim</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>shape of the wave</source>
        <translation>dalganın biçimi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Core</source>
        <translation>Çekirdek</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>finite centre: 0 winds without end, larger keeps the swirl&apos;s eye clean</source>
        <translation>sonlu merkez: 0 sonsuzca sarar, daha büyüğü girdabın gözünü temiz tutar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Teeth</source>
        <translation>Dişler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tooth positions along the normal, from the origin, increasing</source>
        <translation>dişlerin normal boyunca, başlangıç noktasından itibaren artan konumları</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>largest shift, midway between two teeth; its sign is the direction</source>
        <translation>en büyük kayma, iki diş arasının ortasında; işareti yöndür</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Profile</source>
        <translation>Profil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tooth profile |sin|^p: small is blunt, large is pointed</source>
        <translation>diş profili |sin|^p: küçüğü küt, büyüğü sivri</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Field</source>
        <translation>Alan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the velocity field: a lattice of cells or one cavity</source>
        <translation>hız alanı: bir hücre örgüsü ya da tek bir oyuk</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Size</source>
        <translation>Boyut</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>size of a cell (cells) or of the box (cavity)</source>
        <translation>bir hücrenin (hücreler) ya da kutunun (oyuk) boyutu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed</source>
        <translation>Hız</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>design units per time unit</source>
        <translation>zaman birimi başına desen birimi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed of the flow; its sign is the sense of turning</source>
        <translation>akışın hızı; işareti dönüş yönüdür</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time</source>
        <translation>Süre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>time units</source>
        <translation>zaman birimi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>how long the flow runs</source>
        <translation>akışın ne kadar sürdüğü</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Steps</source>
        <translation>Adımlar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>implicit midpoint steps (at least 32 |speed| time max(size) / min(size)^2)</source>
        <translation>örtük orta nokta adımları (en az 32 |hız| süre max(boyut) / min(boyut)^2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Path</source>
        <translation>Yol</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the polyline the stylus is drawn along</source>
        <translation>bizin boyunca çekildiği kırık çizgi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pull</source>
        <translation>Çekiş gücü</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>strength of the pull along the path, about the shift on the track</source>
        <translation>yol boyunca çekişin gücü, aşağı yukarı iz üzerindeki kayma</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>how far to the side the pull reaches</source>
        <translation>çekişin yana ne kadar eriştiği</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reach</source>
        <translation>Erim</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>how far ahead of and behind the stylus the bath moves</source>
        <translation>teknenin bizin ne kadar önünde ve arkasında hareket ettiği</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tines</source>
        <translation>Dişler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 a stylus, more a rake</source>
        <translation>1 bir biz, daha çoğu bir tarak</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>distance between the rake&apos;s tines (required with more than one)</source>
        <translation>tarağın dişleri arası uzaklık (birden çok dişte gerekli)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pressure</source>
        <translation>Basınç</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a pen&apos;s pressure, one value in [0, 1] per path point</source>
        <translation>kalem basıncı, her yol noktası için [0, 1] aralığında bir değer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>integration steps (at least 4 L / reach and the contraction rule)</source>
        <translation>tümleme adımları (en az 4 L / erim ve büzülme kuralı)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drop</source>
        <translation>damla</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>spray</source>
        <translation>serpme</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cylinder</source>
        <translation>silindir</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>line</source>
        <translation>çizgi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>comb</source>
        <translation>tarak</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wave</source>
        <translation>dalga</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>circle</source>
        <translation>daire</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sphere</source>
        <translation>küre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>vortex</source>
        <translation>girdap</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stretch</source>
        <translation>germe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flow</source>
        <translation>akış</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stylus</source>
        <translation>biz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drops</source>
        <translation>damla</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sprays</source>
        <translation>serpme</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cylinders</source>
        <translation>silindir</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lines</source>
        <translation>çizgi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>combs</source>
        <translation>tarak</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>waves</source>
        <translation>dalga</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>circles</source>
        <translation>daire</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>spheres</source>
        <translation>küre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>vortices</source>
        <translation>girdap</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stretches</source>
        <translation>germe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flows</source>
        <translation>akış</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stylus strokes</source>
        <translation>biz çekişi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stone</source>
        <translation>Battal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>battal: drops only, big first, later colours smaller</source>
        <translation>battal: yalnızca damlalar, önce büyükler, sonraki renkler daha küçük</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gel git</source>
        <translation>Gel-git</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stone combed one way and back (come and go)</source>
        <translation>battalın bir yöne ve geri taranması (gel-git)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Chevron</source>
        <translation>Zikzak</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gel-git, then one wide comb across: rows of chevrons</source>
        <translation>gel-git, sonra enine geniş bir tarak: zikzak sıraları</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nonpareil</source>
        <translation>Kılçık</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gel-git, then a fine comb across: rows of small points</source>
        <translation>gel-git, sonra enine ince bir tarak: küçük uç sıraları</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bouquet</source>
        <translation>Buket</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nonpareil, then a rake in a serpentine: rows of fans</source>
        <translation>kılçık, sonra kıvrım kıvrım bir tarak: yelpaze sıraları</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Peacock</source>
        <translation>Tavus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bouquet, then the rake back between: rows of eyes</source>
        <translation>buket, sonra aralardan geri tarak: göz sıraları</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>French curl</source>
        <translation>Fransız kıvrımı</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>curls on a grid over a nonpareil or gel-git</source>
        <translation>kılçık ya da gel-git üzerinde bir ızgaraya dizilmiş kıvrımlar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spanish wave</source>
        <translation>İspanyol dalgası</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stone rocked into bands (a stretch pass)</source>
        <translation>şeritlere sallanmış battal (bir germe geçişi)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Birds nest</source>
        <translation>Bülbül yuvası</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bülbül yuvası: a small curl in each drop</source>
        <translation>bülbül yuvası: her damlada küçük bir kıvrım</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shawl</source>
        <translation>Şal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>şal: gel-git, then a wide comb in long waves</source>
        <translation>şal: gel-git, sonra uzun dalgalarla geniş bir tarak</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tiger eye</source>
        <translation>Kaplan gözü</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stone sprinkled with small bright spots</source>
        <translation>küçük parlak beneklerle serpilmiş battal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zebra</source>
        <translation>Zebra</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bull&apos;s-eyes of two inks combed into stripes</source>
        <translation>iki boyalı hedef halkalarının şeritlere taranması</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>First paper</source>
        <translation>İlk kâğıt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stone, combs both ways across and down, a wave (Lu et al. 2012)</source>
        <translation>battal, enine ve boyuna iki yönde taraklar, bir dalga (Lu vd. 2012)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hearts</source>
        <translation>Kalpler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ebru hearts: rows of ringed drops, a stylus drawn through each row</source>
        <translation>ebru kalpleri: halkalı damla sıraları, her sıradan bir biz geçirilir</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tulip</source>
        <translation>Lale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lale: ringed drops pulled into cups by a short stroke each</source>
        <translation>lale: her biri kısa bir çekişle kâse biçimine çekilen halkalı damlalar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Carnation</source>
        <translation>Karanfil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>karanfil: ringed drops fringed by short strokes round the edge</source>
        <translation>karanfil: kenarı kısa çekişlerle saçaklanmış halkalı damlalar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Curls</source>
        <translation>Kıvrımlar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>free-hand French curl: a stylus drawn in spirals through a gel-git</source>
        <translation>serbest elle Fransız kıvrımı: bir gel-git içinden sarmallar çizen bir biz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Veined</source>
        <translation>Damarlı</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>solid: spheres of ink drawn into veins by combs</source>
        <translation>katı: taraklarla damarlara çekilmiş boya küreleri</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Agate</source>
        <translation>Akik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>solid: columns of banded ink, waved</source>
        <translation>katı: dalgalandırılmış, şerit şerit boya sütunları</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Granite</source>
        <translation>Granit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>solid: speckles over close-packed grains</source>
        <translation>katı: sık dizilmiş taneler üzerinde benekler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>styluses</source>
        <translation>biz çekişi</translation>
    </message>
</context>
<context>
    <name>marbler::ui</name>
    <message>
        <location filename="../app/editor/BathSizes.cpp" line="+24"/>
        <source>&amp;Square</source>
        <translation>&amp;Kare</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>A4 &amp;portrait</source>
        <translation>A4 &amp;dikey</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A4 &amp;landscape</source>
        <translation>A4 &amp;yatay</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;16:9 (wide)</source>
        <translation>&amp;16:9 (geniş)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;9:16 (tall)</source>
        <translation>&amp;9:16 (uzun)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Flat bath of si&amp;ze</source>
        <translation>Bu &amp;boyutta düz tekne</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Solid bl&amp;ock of size</source>
        <translation>Bu b&amp;oyutta katı blok</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>A blank bath %1 × %2 design units</source>
        <translation>%1 × %2 desen birimi boş bir tekne</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A blank block %1 × %2 × %3 design units</source>
        <translation>%1 × %2 × %3 desen birimi boş bir blok</translation>
    </message>
    <message>
        <location filename="../app/shared/Help.cpp" line="+62"/>
        <source>View</source>
        <translation>Görünüm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show or hide %1</source>
        <translation>%1 göster veya gizle</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Keys</source>
        <translation>Tuşlar</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Does</source>
        <translation>İşlev</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Menu</source>
        <translation>Menü</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&lt;h2&gt;Marbler %1&lt;/h2&gt;&lt;p&gt;A workbench for breeding marbled designs, after &lt;i&gt;mathematical marbling&lt;/i&gt; (Lu, Jaffer, Jin, Zhao, Mao, IEEE CG&amp;amp;A 2012).&lt;/p&gt;</source>
        <translation>&lt;h2&gt;Marbler %1&lt;/h2&gt;&lt;p&gt;Ebru desenleri üretmek için bir tezgâh; &lt;i&gt;matematiksel ebru&lt;/i&gt; çalışmasına dayanır (Lu, Jaffer, Jin, Zhao, Mao, IEEE CG&amp;amp;A 2012).&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Qt</source>
        <translation>Qt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OpenImageIO</source>
        <translation>OpenImageIO</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not loaded: it loads on the first export to EXR, JPEG or another format beyond PNG and TIFF</source>
        <translation>yüklenmedi: PNG ve TIFF dışında EXR, JPEG veya başka bir biçime ilk dışa aktarımda yüklenir</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Renderer</source>
        <translation>İşleyici</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>being chosen…</source>
        <translation>seçiliyor…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;p&gt;Choose the renderer in View ▸ Renderer; the environment variable %1=auto|gpu|cpu overrides it.&lt;/p&gt;</source>
        <translation>&lt;p&gt;İşleyiciyi Görünüm ▸ İşleyici menüsünden seçin; %1=auto|gpu|cpu ortam değişkeni bu seçimi geçersiz kılar.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/shared/Lineage.cpp" line="-21"/>
        <source>Alter</source>
        <translation>Değiştir</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Recombine</source>
        <translation>Yeniden birleştir</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Swap</source>
        <translation>Takas</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Change initial state</source>
        <translation>Başlangıcı değiştir</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Wildcard</source>
        <translation>Joker</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Colourway</source>
        <translation>Renk seçeneği</translation>
    </message>
    <message>
        <location filename="../app/shared/MeshChooser.cpp" line="+7"/>
        <source>%1: no such mesh file</source>
        <translation>%1: böyle bir ağ dosyası yok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: not a mesh file</source>
        <translation>%1: bir ağ dosyası değil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: the mesh file cannot be read (permission denied)</source>
        <translation>%1: ağ dosyası okunamıyor (izin verilmedi)</translation>
    </message>
    <message>
        <location filename="../app/workbench/SessionStore.cpp" line="+133"/>
        <source>Solid session, %1</source>
        <translation>Katı oturum, %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Flat session, %1</source>
        <translation>Düz oturum, %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>generation %1</source>
        <translation>%1. nesil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>solid</source>
        <translation>katı</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flat</source>
        <translation>düz</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>changed %1</source>
        <translation>%1 değiştirildi</translation>
    </message>
    <message>
        <location filename="../app/shared/Language.cpp" line="+104"/>
        <source>&amp;Language</source>
        <translation>&amp;Dil</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;System language</source>
        <translation>&amp;Sistem dili</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The window&apos;s language from the next start of Marbler</source>
        <translation>Marbler&apos;ın bir sonraki açılışından itibaren pencerenin dili</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The language changes when Marbler starts again</source>
        <translation>Dil, Marbler yeniden başladığında değişir</translation>
    </message>
</context>
<context>
    <name>marbler::ui::AnimationExportDialog</name>
    <message>
        <location filename="../app/editor/AnimationExport.cpp" line="+59"/>
        <location line="+105"/>
        <source>Export animation</source>
        <translation>Animasyonu dışa aktar</translation>
    </message>
    <message>
        <location line="-103"/>
        <source>PNG frames (a folder)</source>
        <translation>PNG kareleri (bir klasör)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GIF</source>
        <translation>GIF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>WebP (animated)</source>
        <translation>WebP (hareketli)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MP4 (H.264)</source>
        <translation>MP4 (H.264)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>WebM (VP9)</source>
        <translation>WebM (VP9)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>What to write: a folder of PNG frames (each carries the design it shows), an animated image or a video</source>
        <translation>Ne yazılacak: PNG karelerinden bir klasör (her kare gösterdiği deseni taşır), hareketli bir görüntü veya bir video</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The file to write, or for PNG frames a new or empty folder</source>
        <translation>Yazılacak dosya; PNG kareleri için yeni veya boş bir klasör</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Browse…</source>
        <translation>&amp;Gözat…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose where to write the animation</source>
        <translation>Animasyonun nereye yazılacağını seçin</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> px</source>
        <translation> piksel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Width of each frame in pixels</source>
        <translation>Her karenin piksel cinsinden genişliği</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Height of each frame in pixels</source>
        <translation>Her karenin piksel cinsinden yüksekliği</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Number of frames: the first shows the bare bath, the last the whole design</source>
        <translation>Kare sayısı: ilki boş tekneyi, sonuncusu desenin tamamını gösterir</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Frames a second of a video or animated image</source>
        <translation>Bir videonun veya hareketli görüntünün saniyedeki kare sayısı</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> s</source>
        <translation> sn</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>How long the animation plays: the frames at the frame rate (changing it sets the number of frames)</source>
        <translation>Animasyonun süresi: kare hızıyla oynatılan kareler (değiştirmek kare sayısını belirler)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>&amp;Format:</source>
        <translation>&amp;Biçim:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Save to:</source>
        <translation>&amp;Kaydedilecek yer:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Si&amp;ze:</source>
        <translation>B&amp;oyut:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>F&amp;rames:</source>
        <translation>&amp;Kareler:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frames a &amp;second:</source>
        <translation>&amp;Saniyedeki kare:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Duration:</source>
        <translation>&amp;Süre:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export</source>
        <translation>Dışa aktar</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Folder for the PNG frames</source>
        <translation>PNG kareleri için klasör</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 files (*.%2)</source>
        <translation>%1 dosyaları (*.%2)</translation>
    </message>
</context>
<context>
    <name>marbler::ui::AnimationExportJob</name>
    <message>
        <location line="+59"/>
        <source>Writing the making of the design…</source>
        <translation>Desenin yapılışı yazılıyor…</translation>
    </message>
</context>
<context>
    <name>marbler::ui::ColourwaysController</name>
    <message>
        <location filename="../app/workbench/ColourwaysController.cpp" line="+56"/>
        <source>&amp;Colourways</source>
        <translation>&amp;Renk seçenekleri</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Breed only palettes, as textile designers make colourways: with one design picked, fills the grid with it and eight colourways of it (Ctrl+5)</source>
        <translation>Tekstil tasarımcılarının renk seçenekleri yaptığı gibi yalnızca paletleri üret: bir desen seçiliyken ızgarayı o desenle ve onun sekiz renk seçeneğiyle doldurur (Ctrl+5)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Export colourway sheet…</source>
        <translation>Renk seçenekleri &amp;sayfasını dışa aktar…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The grid&apos;s designs side by side in one PNG or TIFF image, each named</source>
        <translation>Izgaradaki desenler yan yana, tek bir PNG veya TIFF görüntüsünde, her biri adıyla</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Colourway sheet with ink c&amp;hips</source>
        <translation>Renk seçenekleri sayfasında &amp;boya örnekleri</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Put each design&apos;s inks, with their hex values, under its name on the sheet</source>
        <translation>Her desenin boyalarını onaltılık değerleriyle birlikte sayfada adının altına koy</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Colourways off: the operators breed whole designs again</source>
        <translation>Renk seçenekleri kapalı: işlemler yine desenlerin tamamını üretir</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Colourways on: Alter varies the picked design&apos;s palette, Recombine mixes the parents&apos; palettes; the structure stays</source>
        <translation>Renk seçenekleri açık: Değiştir seçili desenin paletini çeşitlendirir, Yeniden birleştir ebeveynlerin paletlerini karıştırır; yapı aynı kalır</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Colourways of %1</source>
        <translation>%1 renk seçenekleri</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+51"/>
        <source>Cannot make colourways</source>
        <translation>Renk seçenekleri yapılamıyor</translation>
    </message>
    <message>
        <location line="-48"/>
        <source>Generation %1: %2 and eight colourways of it</source>
        <translation>%1. nesil: %2 ve onun sekiz renk seçeneği</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Colourways of the parent: its palette varied, its structure kept; the slider sets how much</source>
        <translation>Ebeveynin renk seçenekleri: paleti çeşitlenir, yapısı korunur; kaydırıcı ne kadar olacağını belirler</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Colourways whose palettes mix the parents&apos; inks; the structure of each is kept</source>
        <translation>Paletleri ebeveynlerin boyalarını karıştıran renk seçenekleri; her birinin yapısı korunur</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Off in Colourways mode: %1 changes the structure, which colourways keep. Turn Breed ▸ Colourways off to use it</source>
        <translation>Renk seçenekleri kipinde kapalı: %1 yapıyı değiştirir, renk seçenekleri ise yapıyı korur. Kullanmak için Üret ▸ Renk seçenekleri&apos;ni kapatın</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 is off in Colourways mode: colourways keep the structure</source>
        <translation>%1 renk seçenekleri kipinde kapalı: renk seçenekleri yapıyı korur</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Colourways: generation %1</source>
        <translation>Renk seçenekleri: %1. nesil</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>A colourway sheet is being written already</source>
        <translation>Bir renk seçenekleri sayfası zaten yazılıyor</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>No designs to put on a sheet yet</source>
        <translation>Sayfaya konacak desen henüz yok</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+45"/>
        <source>Export colourway sheet</source>
        <translation>Renk seçenekleri sayfasını dışa aktar</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>PNG image (*.png);;TIFF image (*.tif *.tiff)</source>
        <translation>PNG görüntüsü (*.png);;TIFF görüntüsü (*.tif *.tiff)</translation>
    </message>
    <message>
        <location line="+14"/>
        <location line="+24"/>
        <source>Cannot export the colourway sheet</source>
        <translation>Renk seçenekleri sayfası dışa aktarılamıyor</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>Rendering the colourway sheet…</source>
        <translation>Renk seçenekleri sayfası işleniyor…</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Colourway sheet cancelled</source>
        <translation>Renk seçenekleri sayfası iptal edildi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>marbler::ui::DesignCell</name>
    <message>
        <location filename="../app/workbench/DesignCell.cpp" line="+26"/>
        <source>Design %1</source>
        <translation>Desen %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Click to choose as a parent, double-click to open large, F2 to rename, right-click for locks and favourites. Drop a genome file, or a PNG or TIFF Marbler exported, here to load it.</source>
        <translation>Ebeveyn seçmek için tıklayın, büyük açmak için çift tıklayın, yeniden adlandırmak için F2&apos;ye basın, kilitler ve gözdeler için sağ tıklayın. Yüklemek için buraya bir genom dosyası ya da Marbler&apos;ın dışa aktardığı bir PNG veya TIFF bırakın.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Changed: %1

%2</source>
        <translation>Değişen: %1

%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Note: %1

%2</source>
        <translation>Not: %1

%2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>selected as a parent</source>
        <translation>ebeveyn olarak seçili</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>Empty
open or drop a design here</source>
        <translation>Boş
burada bir desen açın veya bırakın</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>rendering…</source>
        <translation>işleniyor…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot render: %1</source>
        <translation>İşlenemiyor: %1</translation>
    </message>
</context>
<context>
    <name>marbler::ui::DesignDialog</name>
    <message>
        <location filename="../app/shared/DesignDialog.cpp" line="-376"/>
        <location line="+352"/>
        <source>Design %1</source>
        <translation>Desen %1</translation>
    </message>
    <message>
        <location line="-333"/>
        <source>Zoom out (-, wheel)</source>
        <translation>Uzaklaştır (-, tekerlek)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom in (+, wheel)</source>
        <translation>Yakınlaştır (+, tekerlek)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fit</source>
        <translation>Sığdır</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frame the whole object (0)</source>
        <translation>Nesnenin tamamını çerçevele (0)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Show the whole design (0)</source>
        <translation>Desenin tamamını göster (0)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1:1</source>
        <translation>1:1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One design unit to a screen pixel, the scale of an export as many pixels wide as the design is wide (1)</source>
        <translation>Bir desen birimine bir ekran pikseli: desen kaç birim genişse o kadar piksel genişlikte bir dışa aktarımın ölçeği (1)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Magnification of the framed object</source>
        <translation>Çerçevelenen nesnenin büyütmesi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Screen pixels per design unit (100 %: one to one)</source>
        <translation>Desen birimi başına ekran pikseli (yüzde 100: bire bir)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Repeat swatch</source>
        <translation>Tekrar örneği</translation>
    </message>
    <message>
        <location line="-68"/>
        <source>Flat designs only: a solid has no repeat tile</source>
        <translation>Yalnızca düz desenler: katı desenin tekrar karosu yoktur</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show the whole design tiled as its mirror repeat, 2 × 2, to judge the repeat (R)</source>
        <translation>Tekrarı değerlendirmek için desenin tamamını ayna tekrarı olarak 2 × 2 döşenmiş göster (R)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Show the design repeated 2 × 2 as its straight repeat, to judge the repeat (R)</source>
        <translation>Tekrarı değerlendirmek için deseni düz tekrarıyla 2 × 2 göster (R)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show the design repeated 2 × 2 as its half-drop repeat, to judge the repeat (R)</source>
        <translation>Tekrarı değerlendirmek için deseni yarım kaydırmalı tekrarıyla 2 × 2 göster (R)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show the design repeated 2 × 2 as its brick repeat, to judge the repeat (R)</source>
        <translation>Tekrarı değerlendirmek için deseni tuğla tekrarıyla 2 × 2 göster (R)</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>Section</source>
        <translation>Kesit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show a cross-section of the solid instead of the object; move it and turn it to any angle below (S)</source>
        <translation>Nesne yerine katı desenin bir kesitini göster; aşağıda onu taşıyıp istediğiniz açıya döndürebilirsiniz (S)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&amp;Save genome…</source>
        <translation>Genomu &amp;kaydet…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the design as a genome file (Ctrl+S)</source>
        <translation>Deseni bir genom dosyası olarak kaydet (Ctrl+S)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export image…</source>
        <translation>Görüntüyü &amp;dışa aktar…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Render the design to PNG, TIFF, EXR or JPEG at any size, or a flat one to SVG (Ctrl+E)</source>
        <translation>Deseni istenen boyutta PNG, TIFF, EXR veya JPEG olarak, düz bir deseni SVG olarak işle (Ctrl+E)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Copy genome</source>
        <translation>Genomu &amp;kopyala</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Put the design&apos;s genome on the clipboard as text, to paste into the workbench or anywhere else (%1)</source>
        <translation>Desenin genomunu metin olarak panoya koy; tezgâha veya başka bir yere yapıştırmak için (%1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Open in e&amp;ditor</source>
        <translation>&amp;Düzenleyicide aç</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Edit this design step by step in the editor (Ctrl+Shift+D)</source>
        <translation>Bu deseni düzenleyicide adım adım düzenle (Ctrl+Shift+D)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Close</source>
        <translation>Kapat</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Rename…</source>
        <translation>Yeniden adlandır…</translation>
    </message>
    <message>
        <location line="+156"/>
        <source>Export separations into a folder</source>
        <translation>Renk ayrımlarını bir klasöre aktar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> separations</source>
        <translation> renk ayrımları</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Folders (*)</source>
        <translation>Klasörler (*)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Export image</source>
        <translation>Görüntüyü dışa aktar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SVG drawings (*.svg)</source>
        <translation>SVG çizimleri (*.svg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Images (*%1);;All images (*.png *.tif *.tiff *.exr *.jpg *.jpeg)</source>
        <translation>Görüntüler (*%1);;Tüm görüntüler (*.png *.tif *.tiff *.exr *.jpg *.jpeg)</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>the design</source>
        <translation>desen</translation>
    </message>
</context>
<context>
    <name>marbler::ui::DesignExport</name>
    <message>
        <location filename="../app/shared/DesignExport.cpp" line="+24"/>
        <source>Export cancelled: %1 was not written</source>
        <translation>Dışa aktarım iptal edildi: %1 yazılmadı</translation>
    </message>
    <message>
        <location line="+21"/>
        <location line="+69"/>
        <location line="+21"/>
        <location line="+38"/>
        <source>Cannot export the image</source>
        <translation>Görüntü dışa aktarılamıyor</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>Exporting %1…</source>
        <translation>%1 dışa aktarılıyor…</translation>
    </message>
</context>
<context>
    <name>marbler::ui::DesignView</name>
    <message>
        <location filename="../app/shared/DesignView.cpp" line="+49"/>
        <location line="+218"/>
        <source>Drag to turn the object; wheel, + and - zoom</source>
        <translation>Nesneyi döndürmek için sürükleyin; tekerlek, + ve - yakınlaştırır</translation>
    </message>
    <message>
        <location line="-217"/>
        <source>Wheel, + and - zoom about the pointer; drag to pan</source>
        <translation>Tekerlek, + ve - imleç çevresinde yakınlaştırır; kaydırmak için sürükleyin</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>rendering…</source>
        <translation>işleniyor…</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Cannot render: %1</source>
        <translation>İşlenemiyor: %1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>%L1 %</source>
        <translation>%%L1</translation>
    </message>
    <message>
        <location line="+165"/>
        <source>The cross-section: the section controls below move and turn it</source>
        <translation>Kesit: aşağıdaki kesit denetimleri onu taşır ve döndürür</translation>
    </message>
</context>
<context>
    <name>marbler::ui::EditorCanvas</name>
    <message>
        <location filename="../app/editor/EditorCanvas.cpp" line="+85"/>
        <source>Drag with the current tool (Esc drops the drag); middle or right drag (or Space and drag) pans, the wheel zooms, 0 fits, 1 shows one to one</source>
        <translation>Geçerli araçla sürükleyin (Esc sürüklemeyi bırakır); orta veya sağ tuşla sürükleme (ya da Boşluk ve sürükleme) kaydırır, tekerlek yakınlaştırır, 0 sığdırır, 1 bire bir gösterir</translation>
    </message>
    <message>
        <location line="+479"/>
        <source>%1 %2s</source>
        <translation>%1 %2</translation>
    </message>
</context>
<context>
    <name>marbler::ui::EditorDocument</name>
    <message>
        <location filename="../app/editor/EditorDocument.cpp" line="+451"/>
        <source>Not done: this design&apos;s bath wraps (it is a repeat tile), and %1. Edit ▸ Bath wraps turns the wrap off and allows every tool.</source>
        <translation>Yapılmadı: bu desenin teknesi kenarlardan sarılır (desen bir tekrar karosudur) ve %1. Düzen ▸ Tekne kenarlardan sarılır sarmayı kapatır ve her araca izin verir.</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>Add %1</source>
        <translation>%1 ekle</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Delete %1</source>
        <translation>%1 sil</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Duplicate %1</source>
        <translation>%1 çoğalt</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Move %1 to %2</source>
        <translation>%1, %2 konumuna taşı</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Mute %1</source>
        <translation>%1 sustur</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unmute %1</source>
        <translation>%1 geri aç</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Mute steps %1–%2</source>
        <translation>%1–%2 adımlarını sustur</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unmute steps %1–%2</source>
        <translation>%1–%2 adımlarını geri aç</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Ink %1: %2 → %3</source>
        <translation>Boya %1: %2 → %3</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Add ink %1: %2</source>
        <translation>Boya %1 ekle: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Background: %1 → %2</source>
        <translation>Zemin: %1 → %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Bleed: %1 → %2</source>
        <translation>Yayılma: %1 → %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Wrap the bath</source>
        <translation>Tekneyi kenarlardan sar</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unwrap the bath</source>
        <translation>Tekneyi kenarlardan sarmayı kaldır</translation>
    </message>
    <message>
        <location line="+211"/>
        <source>Delete ink %1: %2</source>
        <translation>Boya %1 sil: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, its steps in ink %1</source>
        <translation>, adımları boya %1 ile</translation>
    </message>
</context>
<context>
    <name>marbler::ui::EditorExports</name>
    <message>
        <location filename="../app/editor/EditorExports.cpp" line="+48"/>
        <location line="+29"/>
        <source>An animation is being written already</source>
        <translation>Bir animasyon zaten yazılıyor</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>Wrote %1</source>
        <translation>%1 yazıldı</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot write the animation</source>
        <translation>Animasyon yazılamıyor</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Animation cancelled; nothing was written</source>
        <translation>Animasyon iptal edildi; hiçbir şey yazılmadı</translation>
    </message>
</context>
<context>
    <name>marbler::ui::EditorFiles</name>
    <message>
        <location filename="../app/editor/EditorFiles.cpp" line="+45"/>
        <source>Designs (*.marble.json *.json *.png *.tif *.tiff);;All files (*)</source>
        <translation>Desenler (*.marble.json *.json *.png *.tif *.tiff);;Tüm dosyalar (*)</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+44"/>
        <source>Untitled design</source>
        <translation>Adsız desen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Save a design opened from an image</source>
        <translation>Bir görüntüden açılan deseni kaydet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>“%1” is an image. Save the design as a design file, or write the image again with the design inside?</source>
        <translation>“%1” bir görüntü. Desen bir desen dosyası olarak mı kaydedilsin, yoksa görüntü desen içinde olacak şekilde yeniden mi yazılsın?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save as design file…</source>
        <translation>Desen dosyası olarak kaydet…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Update the image</source>
        <translation>Görüntüyü güncelle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Render the design into %1 at its size; the picture there is replaced</source>
        <translation>Deseni kendi boyutunda %1 içine işle; oradaki resmin yerini alır</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Save design</source>
        <translation>Deseni kaydet</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Marbler designs (*.marble.json)</source>
        <translation>Marbler desenleri (*.marble.json)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Name “%1”</source>
        <translation>“%1” adını ver</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The file was changed</source>
        <translation>Dosya değiştirildi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>“%1” was changed by another program or window since it was opened here. Overwrite those changes, reload the file (your changes stay in Undo), or save under another name?</source>
        <translation>“%1”, burada açıldıktan sonra başka bir program veya pencere tarafından değiştirildi. O değişikliklerin üzerine mi yazılsın, dosya yeniden mi yüklensin (değişiklikleriniz Geri al&apos;da kalır), yoksa başka bir adla mı kaydedilsin?</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Overwrite</source>
        <translation>Üzerine yaz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reload</source>
        <translation>Yeniden yükle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save as…</source>
        <translation>Farklı kaydet…</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Cannot save the design</source>
        <translation>Desen kaydedilemiyor</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Saved %1</source>
        <translation>%1 kaydedildi</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Reload %1</source>
        <translation>%1 yeniden yükle</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot reload the design</source>
        <translation>Desen yeniden yüklenemiyor</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Reloaded %1; Undo brings your changes back</source>
        <translation>%1 yeniden yüklendi; Geri al değişikliklerinizi geri getirir</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The image is being written already</source>
        <translation>Görüntü zaten yazılıyor</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Writing %1…</source>
        <translation>%1 yazılıyor…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Wrote %1 with the design inside</source>
        <translation>%1, desen içinde olarak yazıldı</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot write the image</source>
        <translation>Görüntü yazılamıyor</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cancelled; the image is as it was</source>
        <translation>İptal edildi; görüntü olduğu gibi kaldı</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Replace the file?</source>
        <translation>Dosyanın yerine yazılsın mı?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>“%1” exists already. Replace it?</source>
        <translation>“%1” zaten var. Yerine yazılsın mı?</translation>
    </message>
    <message>
        <location line="+27"/>
        <location line="+16"/>
        <source>Cannot open the design</source>
        <translation>Desen açılamıyor</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>No recent designs</source>
        <translation>Son desen yok</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open a design</source>
        <translation>Bir desen aç</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>A picture for the bath</source>
        <translation>Tekne için bir resim</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Images (*.png *.jpg *.jpeg *.tif *.tiff *.webp *.bmp)</source>
        <translation>Görüntüler (*.png *.jpg *.jpeg *.tif *.tiff *.webp *.bmp)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Unsaved changes</source>
        <translation>Kaydedilmemiş değişiklikler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>“%1” has changes that are not saved. Save them?</source>
        <translation>“%1” içinde kaydedilmemiş değişiklikler var. Kaydedilsin mi?</translation>
    </message>
</context>
<context>
    <name>marbler::ui::EditorWindow</name>
    <message>
        <location filename="../app/editor/EditorWindow.cpp" line="+229"/>
        <source>Steps</source>
        <translation>Adımlar</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Inks</source>
        <translation>Boyalar</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Tool</source>
        <translation>Araç</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Timeline</source>
        <translation>Zaman çizelgesi</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;File</source>
        <translation>&amp;Dosya</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New design</source>
        <translation>&amp;Yeni desen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Blank &amp;flat bath</source>
        <translation>Boş &amp;düz tekne</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Blank &amp;solid block</source>
        <translation>Boş &amp;katı blok</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Random design</source>
        <translation>&amp;Rastgele desen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From a &amp;picture…</source>
        <translation>Bir &amp;resimden…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A flat design whose bath is a picture (its source)</source>
        <translation>Teknesi bir resim (kaynağı) olan düz bir desen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open…</source>
        <translation>&amp;Aç…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open &amp;recent</source>
        <translation>&amp;Son açılanlar</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Save</source>
        <translation>&amp;Kaydet</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save &amp;as…</source>
        <translation>&amp;Farklı kaydet…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+Shift+S</source>
        <translation>Ctrl+Shift+S</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export image…</source>
        <translation>Görüntüyü &amp;dışa aktar…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export &amp;animation…</source>
        <translation>&amp;Animasyonu dışa aktar…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Baked onto %1</source>
        <translation>Nesneye pişirildi: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Send to &amp;grid</source>
        <translation>&amp;Izgaraya gönder</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sent to the breeding grid</source>
        <translation>Üretim ızgarasına gönderildi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+G</source>
        <translation>Ctrl+G</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Put this design into the breeding grid as a new design to breed from</source>
        <translation>Bu deseni, ondan üretmek için üretim ızgarasına yeni bir desen olarak koy</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Recover &amp;unsaved designs…</source>
        <translation>Kaydedilmemiş desenleri &amp;kurtar…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Designs that editors left unsaved when Marbler stopped, kept until you discard them</source>
        <translation>Marbler durduğunda düzenleyicilerin kaydetmeden bıraktığı desenler; siz atana dek saklanır</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Close</source>
        <translation>&amp;Kapat</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Edit</source>
        <translation>Dü&amp;zen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Undo</source>
        <translation>&amp;Geri al</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Redo</source>
        <translation>&amp;Yinele</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+Shift+Z</source>
        <translation>Ctrl+Shift+Z</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Y</source>
        <translation>Ctrl+Y</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Re&amp;name…</source>
        <translation>Yeniden &amp;adlandır…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Names the design and gives it a note (one undo step)</source>
        <translation>Desene bir ad ve bir not verir (tek geri alma adımı)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Bath &amp;wraps (straight repeat)</source>
        <translation>Tekne &amp;kenarlardan sarılır (düz tekrar)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Tools</source>
        <translation>&amp;Araçlar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tools</source>
        <translation>Araçlar</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>&amp;View</source>
        <translation>&amp;Görünüm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Fit</source>
        <translation>&amp;Sığdır</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>0</source>
        <translation>0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom &amp;in</source>
        <translation>&amp;Yakınlaştır</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom &amp;out</source>
        <translation>&amp;Uzaklaştır</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Compare two states</source>
        <translation>İki durumu &amp;karşılaştır</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+K</source>
        <translation>Ctrl+K</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Play the making</source>
        <translation>Yapılışı &amp;oynat</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Show on &amp;object</source>
        <translation>&amp;Nesne üzerinde göster</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Ctrl+Shift+O</source>
        <translation>Ctrl+Shift+O</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show the design on an object beside the canvas, updated after each edit</source>
        <translation>Deseni tuvalin yanında bir nesne üzerinde göster; her düzenlemeden sonra güncellenir</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Repeat preview</source>
        <translation>&amp;Tekrar önizlemesi</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;Off</source>
        <translation>&amp;Kapalı</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Plain repeat (3 × 3)</source>
        <translation>&amp;Düz tekrar (3 × 3)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+R</source>
        <translation>Ctrl+Shift+R</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Mirror repeat (3 × 3)</source>
        <translation>&amp;Ayna tekrarı (3 × 3)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+M</source>
        <translation>Ctrl+Shift+M</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Show the design tiled 3 × 3, plainly or as the mirror repeat tile, to judge its seams</source>
        <translation>Eklerini değerlendirmek için deseni 3 × 3 döşenmiş göster: düz ya da ayna tekrarı karosu olarak</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Help</source>
        <translation>&amp;Yardım</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Editor &amp;guide</source>
        <translation>Düzenleyici &amp;kılavuzu</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>How the editor works, and every keyboard shortcut</source>
        <translation>Düzenleyicinin nasıl çalıştığı ve tüm klavye kısayolları</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Marbler editor guide</source>
        <translation>Marbler düzenleyici kılavuzu</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&lt;h2&gt;The editor&lt;/h2&gt;&lt;p&gt;A design is a list of steps: inks dropped on the bath, then strokes that move them. Pick a tool, then click or drag on the canvas; a new step goes after the selected step (or at the timeline&apos;s point) and the canvas shows the design just after it. The stylus draws free-hand: its path follows the drag (a pen&apos;s pressure too), the panel sets its pull, reach and rake, and its path&apos;s points are its handles.&lt;/p&gt;&lt;p&gt;Select a step to change it in the form or with its handles, however far back; mute, duplicate, move or delete it from the list. Undo and redo work from anywhere; edits you undo and then leave by making another stay under History ▸ Other branches, one click away.&lt;/p&gt;&lt;p&gt;The timeline scrubs through the making of the design, plays it and compares two states. Inks holds the palette and the bath&apos;s colour.&lt;/p&gt;&lt;h3&gt;Keys&lt;/h3&gt;</source>
        <translation>&lt;h2&gt;Düzenleyici&lt;/h2&gt;&lt;p&gt;Bir desen bir adımlar listesidir: önce tekneye serpilen boyalar, sonra onları hareket ettiren çekişler. Bir araç seçin, sonra tuvale tıklayın veya sürükleyin; yeni adım seçili adımın (ya da zaman çizelgesindeki noktanın) ardına gelir ve tuval deseni o adımın hemen sonrasıyla gösterir. Biz serbest elle çizer: izi sürüklemeyi izler (kalemin basıncını da), panel çekişini, erimini ve tarağını belirler, izinin noktaları da tutamaçlarıdır.&lt;/p&gt;&lt;p&gt;Bir adımı, ne kadar geride olursa olsun, formda ya da tutamaçlarıyla değiştirmek için seçin; listeden susturun, çoğaltın, taşıyın veya silin. Geri al ve yinele her yerden çalışır; geri alıp sonra başka bir düzenlemeyle bıraktığınız düzenlemeler Geçmiş ▸ Diğer dallar altında, bir tık ötede kalır.&lt;/p&gt;&lt;p&gt;Zaman çizelgesi desenin yapılışında gezinir, onu oynatır ve iki durumu karşılaştırır. Boyalar paleti ve teknenin rengini tutar.&lt;/p&gt;&lt;h3&gt;Tuşlar&lt;/h3&gt;</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Added as step %1 of %2; the timeline shows the design up to it (End shows all)</source>
        <translation>%2 adımın %1. adımı olarak eklendi; zaman çizelgesi deseni bu adıma kadar gösteriyor (End hepsini gösterir)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Ink %1 picked</source>
        <translation>Boya %1 seçildi</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The bare bath</source>
        <translation>Boş tekne</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>A design holds at most %1 inks</source>
        <translation>Bir desende en çok %1 boya olabilir</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Ink %1 is laid by steps and there is no other ink for them</source>
        <translation>Boya %1 adımlar tarafından seriliyor ve onlar için başka boya yok</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Palette: %1</source>
        <translation>Palet: %1</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>The bath wraps: the design is a repeat tile, and takes only spray and stretch along an axis. Turn it off to use every tool.</source>
        <translation>Tekne kenarlardan sarılır: desen bir tekrar karosudur ve yalnızca serpme ile bir eksen boyunca germe alır. Her aracı kullanmak için bunu kapatın.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Make the bath wrap: the design becomes a straight-repeat tile</source>
        <translation>Tekneyi kenarlardan sar: desen düz tekrarlı bir karo olur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This design cannot wrap: %1</source>
        <translation>Bu desenin teknesi kenarlardan sarılamaz: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 (not in a bath that wraps: turn off Edit ▸ Bath wraps to use it)</source>
        <translation>%1 (kenarlardan sarılan bir teknede olmaz: kullanmak için Düzen ▸ Tekne kenarlardan sarılır seçeneğini kapatın)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source> · ink %1</source>
        <translation> · boya %1</translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n adım</numerusform>
        </translation>
    </message>
    <message>
        <location line="+55"/>
        <source>%1[*] — Marbler editor</source>
        <translation>%1[*] — Marbler düzenleyicisi</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Rename to “%1”</source>
        <translation>“%1” olarak yeniden adlandır</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Renamed to “%1”</source>
        <translation>“%1” olarak yeniden adlandırıldı</translation>
    </message>
</context>
<context>
    <name>marbler::ui::ExportSettingsDialog</name>
    <message>
        <location filename="../app/shared/ExportSettingsDialog.cpp" line="+14"/>
        <source>Export image</source>
        <translation>Görüntüyü dışa aktar</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>PNG (8-bit sRGB)</source>
        <translation>PNG (8 bit sRGB)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>JPEG (8-bit sRGB)</source>
        <translation>JPEG (8 bit sRGB)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TIFF (8-bit sRGB)</source>
        <translation>TIFF (8 bit sRGB)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TIFF (16-bit sRGB, for print)</source>
        <translation>TIFF (16 bit sRGB, baskı için)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OpenEXR (linear half float)</source>
        <translation>OpenEXR (doğrusal yarım kayan nokta)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>SVG (vector)</source>
        <translation>SVG (vektör)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Separations (a mask per ink and an indexed PNG, in a folder)</source>
        <translation>Renk ayrımları (her boya için bir maske ve dizinli bir PNG, bir klasörde)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>For screen and block printers: one greyscale mask per ink and the background, and an indexed PNG whose palette is the inks (marbler render --separations)</source>
        <translation>Serigrafi ve blok baskıcılar için: her boya ve zemin için bir gri tonlu maske ve paleti boyalar olan dizinli bir PNG (marbler render --separations)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The file format; a 16-bit TIFF keeps the smooth gradients of an antialiased render for further grading, EXR keeps linear light</source>
        <translation>Dosya biçimi; 16 bit TIFF kenar yumuşatmalı bir işlemenin yumuşak geçişlerini sonraki renk ayarları için korur, EXR doğrusal ışığı korur</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Format</source>
        <translation>&amp;Biçim</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The image&apos;s width in the unit beside; the height follows the design&apos;s proportions</source>
        <translation>Görüntünün yandaki birimle genişliği; yükseklik desenin oranlarını izler</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+243"/>
        <source>pixels</source>
        <translation>piksel</translation>
    </message>
    <message>
        <location line="-242"/>
        <source>cm</source>
        <translation>cm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inches</source>
        <translation>inç</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pixels, or a print size at the resolution below; changing it converts the width</source>
        <translation>Piksel ya da aşağıdaki çözünürlükte bir baskı boyutu; değiştirmek genişliği dönüştürür</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Dots per inch: turns a print size into pixels, and is written into the file</source>
        <translation>İnç başına nokta: baskı boyutunu piksele çevirir ve dosyaya yazılır</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (marbler render --aa %2)</source>
        <translation>%1 (marbler render --aa %2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Antialiasing: more samples a pixel give smoother edges and a slower render</source>
        <translation>Kenar yumuşatma: piksel başına daha çok örnek, daha yumuşak kenarlar ve daha yavaş bir işleme demektir</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Width</source>
        <translation>&amp;Genişlik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Unit</source>
        <translation>&amp;Birim</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Resolution (dpi)</source>
        <translation>&amp;Çözünürlük (dpi)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Antialiasing</source>
        <translation>&amp;Kenar yumuşatma</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mirror repeat tile (2 × 2): twice the width and height</source>
        <translation>Ayna tekrarı karosu (2 × 2): iki kat genişlik ve yükseklik</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A seamless tile for print and textiles: the design and its mirror images 2 × 2, so every edge meets its own mirror image (marbler render --repeat mirror)</source>
        <translation>Baskı ve tekstil için eksiz bir karo: desen ve ayna görüntüleri 2 × 2, böylece her kenar kendi ayna görüntüsüyle buluşur (marbler render --repeat mirror)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Repeat</source>
        <translation>&amp;Tekrar</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Straight repeat tile (2 × 2): the design repeated, twice the width and height</source>
        <translation>Düz tekrar karosu (2 × 2): desen tekrarlanır, iki kat genişlik ve yükseklik</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>This design&apos;s bath wraps, so the design is a straight-repeat tile: each edge meets the opposite one without a seam. Ticked, the export shows it 2 × 2 (unticked, the plain export is the tile itself)</source>
        <translation>Bu desenin teknesi kenarlardan sarılır, bu yüzden desen düz tekrarlı bir karodur: her kenar karşısındakiyle eksiz buluşur. İşaretliyse dışa aktarım onu 2 × 2 gösterir (işaretsizse düz dışa aktarım karonun kendisidir)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>SVG: the largest distance between neighbouring vertices of an outline, in design units; larger gives smaller files (marbler svg --tolerance)</source>
        <translation>SVG: bir dış çizginin komşu köşeleri arasındaki en büyük uzaklık, desen birimiyle; daha büyüğü daha küçük dosyalar verir (marbler svg --tolerance)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Tolerance</source>
        <translation>&amp;Tolerans</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Convert to printer profile (CMYK TIFF)…</source>
        <translation>Yazıcı profiline dönüştür (CMYK TIFF)…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Converts the TIFF from sRGB to the CMYK colours of a printer&apos;s ICC profile, which the print shop gives, and embeds it (marbler render --icc)</source>
        <translation>TIFF&apos;i sRGB&apos;den matbaanın verdiği yazıcı ICC profilinin CMYK renklerine dönüştürür ve profili içine gömer (marbler render --icc)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the printer&apos;s .icc file</source>
        <translation>yazıcının .icc dosyası</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The CMYK output profile of the press or paper, an .icc or .icm file</source>
        <translation>Baskı makinesinin ya da kağıdın CMYK çıkış profili, bir .icc veya .icm dosyası</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C&amp;hoose…</source>
        <translation>&amp;Seç…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose the printer&apos;s ICC profile</source>
        <translation>Yazıcının ICC profilini seçin</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Perceptual (default: the whole image fitted to the press)</source>
        <translation>Algısal (varsayılan: tüm görüntü baskıya uydurulur)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Relative colorimetric (exact where printable)</source>
        <translation>Göreli kolorimetrik (basılabilen yerde tam)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Saturation (vivid, for graphics)</source>
        <translation>Doygunluk (canlı, grafikler için)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Absolute colorimetric (proofing, paper white kept)</source>
        <translation>Mutlak kolorimetrik (prova, kağıt beyazı korunur)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How colours the press cannot print are brought into its range (marbler render --intent)</source>
        <translation>Baskı makinesinin basamadığı renklerin onun aralığına nasıl getirileceği (marbler render --intent)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>C&amp;olours</source>
        <translation>&amp;Renkler</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Printer profile</source>
        <translation>&amp;Yazıcı profili</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Intent</source>
        <translation>&amp;Amaç</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>8-bit coverage (antialiased edges)</source>
        <translation>8 bit kaplama (yumuşatılmış kenarlar)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1-bit (on or off, for screens)</source>
        <translation>1 bit (açık ya da kapalı, serigrafi için)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Separations: each mask&apos;s pixels as the share of the ink in them, or on where at least half the pixel is the ink (marbler render --mask-bits)</source>
        <translation>Renk ayrımları: her maske pikseli içindeki boya payı olarak ya da pikselin en az yarısı boyaysa açık (marbler render --mask-bits)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Masks</source>
        <translation>&amp;Maskeler</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Image</source>
        <translation>Görüntü</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Object view (as shown)</source>
        <translation>Nesne görünümü (gösterildiği gibi)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cross-section</source>
        <translation>Kesit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The design on its object, as the view shows it, or a flat cut through the block</source>
        <translation>Nesnesi üzerindeki desen, görünümün gösterdiği gibi, ya da bloktan geçen düz bir kesit</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>x (a y-z plane)</source>
        <translation>x (bir y-z düzlemi)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>y (an x-z plane)</source>
        <translation>y (bir x-z düzlemi)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>z (an x-y plane)</source>
        <translation>z (bir x-y düzlemi)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The axis the cross-section is taken across</source>
        <translation>Kesitin dik alındığı eksen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Where on its axis the cross-section lies, in design units</source>
        <translation>Kesitin ekseni üzerindeki yeri, desen birimiyle</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>across the axis</source>
        <translation>eksene dik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A turned cross-section&apos;s normal as x, y, z (e.g. 1, 1, 0); empty: across the axis</source>
        <translation>Döndürülmüş bir kesitin normali x, y, z olarak (ör. 1, 1, 0); boş: eksene dik</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>&amp;Show</source>
        <translation>&amp;Göster</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A&amp;xis</source>
        <translation>&amp;Eksen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Normal</source>
        <translation>&amp;Normal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Position</source>
        <translation>&amp;Konum</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>Vector outlines in design units (%L1 × %L2)</source>
        <translation>Desen birimiyle vektör dış çizgileri (%L1 × %L2)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%L1 × %L2 pixels</source>
        <translation>%L1 × %L2 piksel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, the tile of a %L1 × %L2 render</source>
        <translation>, %L1 × %L2 bir işlemenin karosu</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (%1 × %2 in at %3 dpi)</source>
        <translation> (%3 dpi&apos;de %1 × %2 inç)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>The widest that fits is %L1 pixels: type at most that in Width.</source>
        <translation>Sığan en büyük genişlik %L1 piksel: Genişlik alanına en çok bunu yazın.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The widest that fits is %L1 %2 at %3 dpi: type at most that in Width, or lower the resolution.</source>
        <translation>%3 dpi&apos;de sığan en büyük genişlik %L1 %2: Genişlik alanına en çok bunu yazın ya da çözünürlüğü düşürün.</translation>
    </message>
    <message>
        <location line="+141"/>
        <source>The image is too large</source>
        <translation>Görüntü çok büyük</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No printer profile</source>
        <translation>Yazıcı profili yok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the printer&apos;s ICC profile (an .icc file from the print shop), or untick Convert to printer profile.</source>
        <translation>Yazıcının ICC profilini (matbaadan bir .icc dosyası) seçin ya da Yazıcı profiline dönüştür seçeneğinin işaretini kaldırın.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cannot use the printer profile</source>
        <translation>Yazıcı profili kullanılamıyor</translation>
    </message>
</context>
<context>
    <name>marbler::ui::FavouritesShelf</name>
    <message>
        <location filename="../app/workbench/FavouritesShelf.cpp" line="+59"/>
        <source>&amp;Restore removed favourite</source>
        <translation>Kaldırılan gözdeyi &amp;geri getir</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Puts the favourite removed last back on the shelf</source>
        <translation>En son kaldırılan gözdeyi rafa geri koyar</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Favourites</source>
        <translation>Gözdeler</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Designs kept aside (F on a cell). Double-click or drag one onto a cell to bring it back.</source>
        <translation>Kenara ayrılan desenler (bir hücrede F). Geri getirmek için birine çift tıklayın veya bir hücreye sürükleyin.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Undo</source>
        <translation>Geri al</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Put the removed favourite back (%1)</source>
        <translation>Kaldırılan gözdeyi geri koy (%1)</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Cannot keep the favourite</source>
        <translation>Gözde saklanamıyor</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Design %1 kept on the favourites shelf</source>
        <translation>Desen %1 gözdeler rafında saklandı</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Put into the grid</source>
        <translation>Izgaraya koy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rename…</source>
        <translation>Yeniden adlandır…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Remove from favourites</source>
        <translation>Gözdelerden kaldır</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Cannot rename the favourite</source>
        <translation>Gözde yeniden adlandırılamıyor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 could not be written</source>
        <translation>%1 yazılamadı</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cannot remove the favourite</source>
        <translation>Gözde kaldırılamıyor</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Removed “%1” from favourites — Undo (%2)</source>
        <translation>“%1” gözdelerden kaldırıldı — Geri al (%2)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Cannot restore the favourite</source>
        <translation>Gözde geri getirilemiyor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The removed favourite could not be put back from %1 to %2.</source>
        <translation>Kaldırılan gözde %1 konumundan %2 konumuna geri konamadı.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>“%1” is back on the favourites shelf</source>
        <translation>“%1” yeniden gözdeler rafında</translation>
    </message>
</context>
<context>
    <name>marbler::ui::HelpMenu</name>
    <message>
        <location filename="../app/workbench/HelpMenu.cpp" line="+26"/>
        <source>&amp;Help</source>
        <translation>&amp;Yardım</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Marbler &amp;guide</source>
        <translation>Marbler &amp;kılavuzu</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>What the operators do, how to breed, and every keyboard shortcut</source>
        <translation>İşlemlerin ne yaptığı, nasıl üretileceği ve tüm klavye kısayolları</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;About Marbler</source>
        <translation>Marbler &amp;hakkında</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Marbler&apos;s version, the libraries it runs with and the renderer in use</source>
        <translation>Marbler&apos;ın sürümü, birlikte çalıştığı kitaplıklar ve kullanılan işleyici</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>About &amp;Qt</source>
        <translation>&amp;Qt hakkında</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The Qt toolkit Marbler is built with</source>
        <translation>Marbler&apos;ın üzerine kurulduğu Qt araç takımı</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Marbler guide</source>
        <translation>Marbler kılavuzu</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 (built with %2)</source>
        <translation>%1 (%2 ile derlendi)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>About Marbler</source>
        <translation>Marbler hakkında</translation>
    </message>
</context>
<context>
    <name>marbler::ui::HistoryDock</name>
    <message>
        <location filename="../app/editor/HistoryDock.cpp" line="+15"/>
        <source>History</source>
        <translation>Geçmiş</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Opened</source>
        <translation>Açıldı</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every edit; click one to go back (or forward) to it</source>
        <translation>Her düzenleme; ona geri (veya ileri) gitmek için birine tıklayın</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Edits you undid and then left by making another: click one to go back to it (the edits you leave stay here)</source>
        <translation>Geri alıp sonra başka bir düzenleme yaparak bıraktığınız düzenlemeler: ona dönmek için birine tıklayın (bıraktığınız düzenlemeler burada kalır)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Other branches</source>
        <translation>Diğer dallar</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Switched to another branch of the history</source>
        <translation>Geçmişin başka bir dalına geçildi</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the opened design</source>
        <translation>açılan desen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>“%1”</source>
        <translation>“%1”</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>After %1: %n more edit(s), last “%2”</source>
        <translation>
            <numerusform>%1 sonrası: %n düzenleme daha, sonuncusu “%2”</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Click to switch to this branch</source>
        <translation>Bu dala geçmek için tıklayın</translation>
    </message>
</context>
<context>
    <name>marbler::ui::LineagePanel</name>
    <message>
        <location filename="../app/workbench/LineagePanel.cpp" line="+25"/>
        <source>Lineage</source>
        <translation>Soy</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Design</source>
        <translation>Desen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Made by</source>
        <translation>Yapan</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Parents</source>
        <translation>Ebeveynler</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Generation</source>
        <translation>Nesil</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Every generation, branches included, and how the designs came to be. Click a design to select it; double-click a generation to go back to it, or a design of another generation to bring it back into the grid.</source>
        <translation>Dallar dahil her nesil ve desenlerin nasıl ortaya çıktığı. Seçmek için bir desene tıklayın; bir nesle dönmek için ona, başka bir neslin desenini ızgaraya geri getirmek için o desene çift tıklayın.</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>Current designs</source>
        <translation>Güncel desenler</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Generations</source>
        <translation>Nesiller</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>design %1</source>
        <translation>desen %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Generation %1</source>
        <translation>%1. nesil</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>The current generation: its designs are in the grid</source>
        <translation>Güncel nesil: desenleri ızgarada</translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+14"/>
        <source>Branch %1</source>
        <translation>Dal %1</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>from generation %1</source>
        <translation>%1. nesilden</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>a new start</source>
        <translation>yeni bir başlangıç</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Design %1: %2</source>
        <translation>Desen %1: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1
Family: %2</source>
        <translation>%1
Aile: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Changed: %1</source>
        <translation>Değişen: %1</translation>
    </message>
</context>
<context>
    <name>marbler::ui::OpenPlacementDialog</name>
    <message>
        <location filename="../app/workbench/OpenPlacement.cpp" line="-120"/>
        <source>design %1</source>
        <translation>desen %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>designs %1 and %2</source>
        <translation>%1 ve %2 desenleri</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Where do the opened designs go?</source>
        <translation>Açılan desenler nereye gitsin?</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n designs</source>
        <translation>
            <numerusform>%n desen</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;b&gt;Opening %1 would replace %2.&lt;/b&gt;</source>
        <translation>&lt;b&gt;%1 açmak %2 yerine geçer.&lt;/b&gt;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Design %1 is a selected parent.</source>
        <translation>Desen %1 seçili bir ebeveyn.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 are selected parents.</source>
        <translation>%1 seçili ebeveynler.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Either way the grid as it is now stays one generation back (Ctrl+Z).</source>
        <translation>Her iki durumda da ızgaranın şimdiki hâli bir nesil geride kalır (Ctrl+Z).</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Replace the selected cell</source>
        <translation>Seçili hücrenin &amp;yerine koy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Replace the selected cells</source>
        <translation>Seçili hücrelerin &amp;yerine koy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Replace all nine designs</source>
        <translation>Dokuz desenin &amp;tümünün yerine koy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Replace %1</source>
        <translation>%1 &amp;yerine koy</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Put the opened designs over %1</source>
        <translation>Açılan desenleri %1 üzerine koy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add as a &amp;new generation</source>
        <translation>&amp;Yeni bir nesil olarak ekle</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A new generation that keeps the parents: the opened designs go into free cells, then over designs that are not parents</source>
        <translation>Ebeveynleri koruyan yeni bir nesil: açılan desenler önce boş hücrelere, sonra ebeveyn olmayan desenlerin üzerine gider</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cancel</source>
        <translation>İptal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Don&apos;t ask again (do the same next time)</source>
        <translation>&amp;Bir daha sorma (gelecek sefer de aynısını yap)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remember this choice; opened designs then go where it says without a question</source>
        <translation>Bu seçimi hatırla; açılan desenler sonra sorulmadan onun söylediği yere gider</translation>
    </message>
</context>
<context>
    <name>marbler::ui::OperatorActions</name>
    <message>
        <location filename="../app/workbench/OperatorActions.cpp" line="+38"/>
        <source>Alter (1 parent)</source>
        <translation>Değiştir (1 ebeveyn)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Offspring with the parent&apos;s strokes perturbed; the slider sets how much</source>
        <translation>Ebeveynin çekişleri sarsılmış yavrular; kaydırıcı ne kadar olacağını belirler</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Recombine (2+ parents)</source>
        <translation>Yeniden birleştir (2+ ebeveyn)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Offspring that take strokes from each of the parents</source>
        <translation>Ebeveynlerin her birinden çekiş alan yavrular</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Swap (2 parents)</source>
        <translation>Takas (2 ebeveyn)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One parent&apos;s initial drops with the other&apos;s strokes, both ways</source>
        <translation>Bir ebeveynin ilk damlaları ötekinin çekişleriyle, iki yönde de</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Change initial state (1 parent)</source>
        <translation>Başlangıcı değiştir (1 ebeveyn)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Offspring with new initial drops under the same strokes</source>
        <translation>Aynı çekişlerin altında yeni ilk damlaları olan yavrular</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>How far %1 moves the strokes: 0 % barely, 100 % a lot</source>
        <translation>%1 çekişleri ne kadar oynatır: yüzde 0 pek az, yüzde 100 çok</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+4"/>
        <location line="+2"/>
        <source> Strength %1 % </source>
        <translation> Güç %%1 </translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 follows when this generation has rendered</source>
        <translation>%1, bu nesil işlendiğinde gelir</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>&amp;Steer by my picks</source>
        <translation>Seçimlerime göre &amp;yönlendir</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Offspring are drawn from many candidates and ranked by what your picks so far say; the status line tells why</source>
        <translation>Yavrular birçok adaydan çekilir ve şimdiye dek yaptığınız seçimlere göre sıralanır; durum satırı nedenini söyler</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Less like this</source>
        <translation>Bunun gibi &amp;daha az</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Marks the selected designs as unlike what you have in mind: steering moves away from them</source>
        <translation>Seçili desenleri aklınızdakine benzemeyen olarak işaretler: yönlendirme onlardan uzaklaşır</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Less like this: click the designs you do not want first</source>
        <translation>Bunun gibi daha az: önce istemediğiniz desenlere tıklayın</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>%n design(s) no longer marked less like this</source>
        <translation>
            <numerusform>%n desen artık “bunun gibi daha az” olarak işaretli değil</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n design(s) marked less like this: the next generation moves away from them</source>
        <translation>
            <numerusform>%n desen “bunun gibi daha az” olarak işaretlendi: sonraki nesil onlardan uzaklaşır</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>marbler::ui::PaletteEditor</name>
    <message>
        <location filename="../app/editor/PaletteEditor.cpp" line="+68"/>
        <source>Turkish ebru</source>
        <translation>Türk ebrusu</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Florentine</source>
        <translation>Floransa</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Suminagashi</source>
        <translation>Suminagashi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ocean</source>
        <translation>Okyanus</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Autumn</source>
        <translation>Sonbahar</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>&amp;Bleed</source>
        <translation>&amp;Yayılma</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Soft ink edges: the width of the blend between inks, in design units (0: sharp)</source>
        <translation>Yumuşak boya kenarları: boyalar arasındaki geçişin genişliği, desen birimiyle (0: keskin)</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Ink %1: click to lay it with the tools, double-click to change its colour</source>
        <translation>Boya %1: araçlarla sermek için tıklayın, rengini değiştirmek için çift tıklayın</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Change colour…</source>
        <translation>Rengi değiştir…</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+68"/>
        <location line="+8"/>
        <source>Delete ink</source>
        <translation>Boyayı sil</translation>
    </message>
    <message>
        <location line="-64"/>
        <source>Add an ink to the palette</source>
        <translation>Palete bir boya ekle</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Delete the current ink from the palette (asks first when steps lay it)</source>
        <translation>Geçerli boyayı paletten sil (adımlar onu seriyorsa önce sorar)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Presets</source>
        <translation>Hazır paletler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replace the inks and the bath with a named palette (one undo step)</source>
        <translation>Boyaları ve tekneyi adı olan bir paletle değiştir (tek geri alma adımı)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The background (the bare bath): click to change its colour</source>
        <translation>Zemin (boş tekne): rengini değiştirmek için tıklayın</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Ink %1 is the only ink, and steps lay it: add another ink first.</source>
        <translation>Boya %1 tek boya ve adımlar onu seriyor: önce başka bir boya ekleyin.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>1 step lays ink %1.</source>
        <translation>1 adım boya %1 seriyor.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 steps lay ink %2.</source>
        <translation>%1 adım boya %2 seriyor.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Delete it and lay them with ink %1, the nearest colour, instead?</source>
        <translation>Silinsin ve onlar yerine en yakın renk olan boya %1 ile mi serilsin?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Delete and re-map</source>
        <translation>&amp;Sil ve yeniden eşle</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Background colour</source>
        <translation>Zemin rengi</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Colour of ink %1</source>
        <translation>Boya %1 rengi</translation>
    </message>
</context>
<context>
    <name>marbler::ui::PaperDialog</name>
    <message>
        <location filename="../app/workbench/PaperDialog.cpp" line="+33"/>
        <source>A5 (148 × 210 mm)</source>
        <translation>A5 (148 × 210 mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A4 (210 × 297 mm)</source>
        <translation>A4 (210 × 297 mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A3 (297 × 420 mm)</source>
        <translation>A3 (297 × 420 mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Letter (8.5 × 11 in)</source>
        <translation>Letter (8,5 × 11 inç)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Square (300 × 300 mm)</source>
        <translation>Kare (300 × 300 mm)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>New marbled paper</source>
        <translation>Yeni ebru kâğıdı</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Custom size</source>
        <translation>Özel boyut</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The sheet the paper is made for; the design is measured in its millimetres (marbler paper --size)</source>
        <translation>Ebru kâğıdının yapılacağı kâğıt; desen bu kâğıdın milimetreleriyle ölçülür (marbler paper --size)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The sheet&apos;s width in millimetres</source>
        <translation>Kâğıdın milimetre cinsinden genişliği</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The sheet&apos;s height in millimetres</source>
        <translation>Kâğıdın milimetre cinsinden yüksekliği</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Inks, one layer of drops each, each later one smaller (marbler paper --colors)</source>
        <translation>Boyalar: her biri bir damla katmanı, sonraki her biri bir öncekinden küçük (marbler paper --colors)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Combing passes along the sheet, each weaker than the one before (marbler paper --passes)</source>
        <translation>Kâğıt boyunca tarak geçişleri, her biri bir öncekinden daha zayıf (marbler paper --passes)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Pastel inks on a white bath</source>
        <translation>Beyaz teknede &amp;pastel boyalar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pale, soft inks instead of random ones on cream (marbler paper --pastel)</source>
        <translation>Krem teknede rastgele boyalar yerine soluk, yumuşak boyalar (marbler paper --pastel)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Golden-ratio drops, wrapping (the post&apos;s)</source>
        <translation>Altın oranlı damlalar, kenarlardan sarılan (yazıdaki tarif)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Classic drops on cream</source>
        <translation>Krem teknede klasik damlalar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>marbler paper --recipe post or classic</source>
        <translation>marbler paper --recipe post veya classic</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The same seed and options make the same paper (marbler paper --seed)</source>
        <translation>Aynı tohum ve seçenekler aynı kâğıdı yapar (marbler paper --seed)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Sheet</source>
        <translation>&amp;Kâğıt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Width</source>
        <translation>&amp;Genişlik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Height</source>
        <translation>&amp;Yükseklik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Colours</source>
        <translation>&amp;Renkler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Combing &amp;passes</source>
        <translation>&amp;Tarak geçişleri</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Recipe</source>
        <translation>Tar&amp;if</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S&amp;eed</source>
        <translation>T&amp;ohum</translation>
    </message>
</context>
<context>
    <name>marbler::ui::ParamForm</name>
    <message>
        <location filename="../app/editor/ParamForm.cpp" line="+210"/>
        <source>The parameters of the selected step</source>
        <translation>Seçili adımın parametreleri</translation>
    </message>
    <message>
        <location line="+77"/>
        <source> [format version %1]</source>
        <translation> [biçim sürümü %1]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>
In the file: &quot;%1&quot;</source>
        <translation>
Dosyada: &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Ink %1</source>
        <translation>Boya %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>x y; x y; ... (2 to %1 points)</source>
        <translation>x y; x y; ... (2 ile %1 arası nokta)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>all 1 (a mouse&apos;s stroke)</source>
        <translation>hepsi 1 (fare ile çekiş)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>How many teeth: more or fewer over the same span</source>
        <translation>Kaç diş: aynı aralıkta daha çok ya da daha az</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+157"/>
        <source>The distance between two teeth, about the same middle</source>
        <translation>İki diş arasındaki uzaklık, aynı orta nokta çevresinde</translation>
    </message>
    <message>
        <location line="-156"/>
        <source>Count</source>
        <translation>Sayı</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spacing</source>
        <translation>Aralık</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>positions, increasing</source>
        <translation>konumlar, artan</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>
Drag to see the change as you go</source>
        <translation>
Değişikliği anında görmek için sürükleyin</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>The mean distance between the teeth, which are unevenly spaced: a new spacing spaces them evenly</source>
        <translation>Eşit aralıklı olmayan dişler arasındaki ortalama uzaklık: yeni bir aralık onları eşit dağıtır</translation>
    </message>
    <message>
        <location line="+104"/>
        <source>%1: point %2 (&quot;%3&quot;) is not two numbers &quot;x y&quot;</source>
        <translation>%1: %2. nokta (&quot;%3&quot;) iki sayı &quot;x y&quot; değil</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: point %2 is the same as point %3; consecutive points must differ</source>
        <translation>%1: %2. nokta %3. noktayla aynı; ardışık noktalar farklı olmalı</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: %2 points; a path has 2 to %3</source>
        <translation>%1: %2 nokta; bir yolun 2 ile %3 arası noktası olur</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: value %2 (&quot;%3&quot;) is not a number</source>
        <translation>%1: %2. değer (&quot;%3&quot;) bir sayı değil</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: value %2 (%3) %4</source>
        <translation>%1: %2. değer (%3) %4</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: %2 values for %3 path points; give one a point, or none for all 1</source>
        <translation>%1: %3 yol noktası için %2 değer; her noktaya bir tane verin ya da hepsi 1 olsun diye hiç vermeyin</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: this stroke would need more than %2 integration steps; split it into shorter strokes</source>
        <translation>%1: bu çekiş %2 tümleme adımından fazlasını gerektirir; onu daha kısa çekişlere bölün</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>marbler::ui::PopulationBar</name>
    <message>
        <location filename="../app/workbench/PopulationBar.cpp" line="+35"/>
        <source> New population: </source>
        <translation> Yeni topluluk: </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>2D designs</source>
        <translation>2B desenler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Solid designs</source>
        <translation>Katı desenler</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>What a new random population holds: flat marbling or solid (volume) marbling</source>
        <translation>Yeni bir rastgele topluluğun içeriği: düz ebru ya da katı (hacimli) ebru</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>What File ▸ New random population (%1) makes</source>
        <translation>Dosya ▸ Yeni rastgele topluluk (%1) ne yapar</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The pattern family of a new random population, or a mix of the craft&apos;s families</source>
        <translation>Yeni bir rastgele topluluğun desen ailesi ya da zanaatin ailelerinin bir karışımı</translation>
    </message>
    <message>
        <location line="+7"/>
        <source> Show on: </source>
        <translation> Göster: </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The object the designs are shown on (drag in a cell to turn it): a built-in or a mesh file; flat designs also flat</source>
        <translation>Desenlerin üzerinde gösterildiği nesne (döndürmek için bir hücrede sürükleyin): yerleşik bir nesne ya da bir ağ dosyası; düz desenler düz de gösterilebilir</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Flat</source>
        <translation>Düz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Flat designs shown flat</source>
        <translation>Düz desenler düz gösterilir</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Mesh file…</source>
        <translation>Ağ dosyası…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show the designs on an OBJ, STL, PLY or glTF file</source>
        <translation>Desenleri bir OBJ, STL, PLY veya glTF dosyası üzerinde göster</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cannot show the mesh</source>
        <translation>Ağ modeli gösterilemiyor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1

The designs stay on what they were shown on.</source>
        <translation>%1

Desenler gösterildikleri nesnede kalır.</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Mixed families</source>
        <translation>Karışık aileler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every cell a different family of the craft (and some free designs)</source>
        <translation>Her hücrede zanaatin farklı bir ailesi (ve birkaç serbest desen)</translation>
    </message>
</context>
<context>
    <name>marbler::ui::PopulationModel</name>
    <message>
        <location filename="../app/workbench/PopulationModel.cpp" line="+24"/>
        <source>Empty workbench</source>
        <translation>Boş tezgâh</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>%1 needs %2 or more parents</source>
        <translation>%1 için %2 veya daha çok ebeveyn gerekir</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 needs 1 parent</source>
        <translation>%1 için 1 ebeveyn gerekir</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 needs exactly %2 parents</source>
        <translation>%1 için tam %2 ebeveyn gerekir</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: there are no designs yet; make a new random population or open designs</source>
        <translation>%1: henüz desen yok; yeni bir rastgele topluluk yapın ya da desen açın</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: click a design to pick it</source>
        <translation>%1: seçmek için bir desene tıklayın</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: click %2 designs</source>
        <translation>%1: %2 desene tıklayın</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>two</source>
        <translation>iki</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2 is picked, click another design</source>
        <translation>%1: %2 seçili, başka bir desene tıklayın</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2 are picked, click one to let it go</source>
        <translation>%1: %2 seçili, bırakmak için birine tıklayın</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 has no room for offspring: every design is a parent, click one to let it go</source>
        <translation>%1 için yavrulara yer yok: her desen bir ebeveyn, bırakmak için birine tıklayın</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 needs two parents of the same kind (flat/solid): one picked design is flat, the other solid</source>
        <translation>%1 için aynı türden (düz/katı) iki ebeveyn gerekir: seçilen desenlerden biri düz, öteki katı</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 needs parents of the same kind (flat/solid): the picked designs mix flat and solid ones</source>
        <translation>%1 için aynı türden (düz/katı) ebeveynler gerekir: seçilen desenlerde düz ve katı olanlar karışık</translation>
    </message>
    <message>
        <location line="+76"/>
        <source>%1 of 1 parent</source>
        <translation>1 ebeveynden %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 of %2 parents</source>
        <translation>%2 ebeveynden %1</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>Design %1&apos;s palette is locked, and colourways change only the palette: unlock it first</source>
        <translation>Desen %1 paleti kilitli ve renk seçenekleri yalnızca paleti değiştirir: önce kilidi açın</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Colourways of 1 parent</source>
        <translation>1 ebeveynin renk seçenekleri</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Colourways mixed from %1 parents</source>
        <translation>%1 ebeveynden karıştırılmış renk seçenekleri</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>New %1 population</source>
        <translation>Yeni %1 topluluğu</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>New random solid population</source>
        <translation>Yeni rastgele katı topluluk</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>New random population</source>
        <translation>Yeni rastgele topluluk</translation>
    </message>
    <message>
        <location line="+196"/>
        <source>%1 (branch %2)</source>
        <translation>%1 (dal %2)</translation>
    </message>
    <message>
        <location line="+109"/>
        <source>generation %1 of the session</source>
        <translation>oturumun %1. nesli</translation>
    </message>
</context>
<context>
    <name>marbler::ui::RenameDialog</name>
    <message>
        <location filename="../app/shared/RenameDialog.cpp" line="+17"/>
        <source>Rename design</source>
        <translation>Deseni yeniden adlandır</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The design&apos;s name: shown under it, offered as its file name, kept in the file</source>
        <translation>Desenin adı: altında gösterilir, dosya adı olarak önerilir, dosyada saklanır</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A note for yourself (optional)</source>
        <translation>Kendiniz için bir not (isteğe bağlı)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shown in the design&apos;s tooltip and kept in its file (meta.note)</source>
        <translation>Desenin araç ipucunda gösterilir ve dosyasında saklanır (meta.note)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Name:</source>
        <translation>&amp;Ad:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>N&amp;ote:</source>
        <translation>&amp;Not:</translation>
    </message>
</context>
<context>
    <name>marbler::ui::RendererMenu</name>
    <message>
        <location filename="../app/workbench/RendererMenu.cpp" line="+19"/>
        <source>&amp;Renderer</source>
        <translation>İş&amp;leyici</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Renderer: &amp;Automatic</source>
        <translation>İşleyici: &amp;Otomatik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OpenGL on a graphics card; the CPU where OpenGL is a software rasteriser (such as llvmpipe) or missing, since the CPU renderer is faster there</source>
        <translation>Ekran kartında OpenGL; OpenGL bir yazılım taramalayıcısıysa (llvmpipe gibi) ya da yoksa CPU, çünkü orada CPU işleyicisi daha hızlıdır</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Renderer: &amp;GPU</source>
        <translation>İşleyici: &amp;GPU</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Always render with OpenGL shaders, even on a software rasteriser (the CPU where there is no OpenGL at all)</source>
        <translation>Bir yazılım taramalayıcısında bile her zaman OpenGL gölgelendiricileriyle işle (hiç OpenGL yoksa CPU)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Renderer: &amp;CPU</source>
        <translation>İşleyici: &amp;CPU</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Always render with the CPU renderer on every core; solid objects are still rasterised by OpenGL where it exists, and coloured by the CPU</source>
        <translation>Her zaman her çekirdekte CPU işleyicisiyle işle; katı nesneler varsa yine OpenGL ile taramalanır ve CPU ile renklendirilir</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1=%2 is set, which overrides this setting</source>
        <translation>%1=%2 tanımlı ve bu ayarı geçersiz kılıyor</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Rendering with %1</source>
        <translation>%1 ile işleniyor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rendering on the %1</source>
        <translation>%1 üzerinde işleniyor</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>marbler::ui::SavedFileNotice</name>
    <message>
        <location filename="../app/shared/SavedFiles.cpp" line="+85"/>
        <source>Show in folder</source>
        <translation>Klasörde göster</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>No file manager opened %1; the file&apos;s path is copied to the clipboard: %2</source>
        <translation>%1 hiçbir dosya yöneticisinde açılamadı; dosyanın yolu panoya kopyalandı: %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Saved %1</source>
        <translation>%1 kaydedildi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open %1 in the file manager</source>
        <translation>%1 dosya yöneticisinde aç</translation>
    </message>
</context>
<context>
    <name>marbler::ui::SectionControls</name>
    <message>
        <location filename="../app/shared/SectionControls.cpp" line="+52"/>
        <source>Section</source>
        <translation>Kesit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The axis the cross-section is cut across; clicks on it place the 3D tools</source>
        <translation>Kesitin dik kesildiği eksen; üzerine yapılan tıklamalar 3B araçları yerleştirir</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Tilt</source>
        <translation>Eğim</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Tilts the section away from its axis (degrees): strokes drawn on it are placed on the tilted plane</source>
        <translation>Kesiti ekseninden eğer (derece): üzerine çizilen çekişler eğik düzleme yerleşir</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Turns the tilt about the section&apos;s axis (degrees)</source>
        <translation>Eğimi kesitin ekseni çevresinde döndürür (derece)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Turn</source>
        <translation>Dönüş</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Normal</source>
        <translation>Normal</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>across the axis</source>
        <translation>eksene dik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The section&apos;s normal as x, y, z (e.g. 1, 1, 0), Enter to turn the section to it; empty: across the axis</source>
        <translation>Kesitin normali x, y, z olarak (ör. 1, 1, 0), kesiti ona döndürmek için Enter; boş: eksene dik</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Where along its axis the cross-section is cut (PgUp / PgDn move it)</source>
        <translation>Kesitin ekseni boyunca nerede kesildiği (PgUp / PgDn taşır)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Where the cross-section is cut, in design units along its axis (or normal)</source>
        <translation>Kesitin nerede kesildiği, ekseni (veya normali) boyunca desen birimiyle</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Object</source>
        <translation>Nesne</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Mesh file…</source>
        <translation>Ağ dosyası…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The object the design is shown on (drag the object to turn it)</source>
        <translation>Desenin üzerinde gösterildiği nesne (döndürmek için nesneyi sürükleyin)</translation>
    </message>
    <message>
        <location line="+81"/>
        <location line="+17"/>
        <source>n·p = </source>
        <translation>n·p = </translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 = </source>
        <translation>%1 = </translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Show the design on a mesh</source>
        <translation>Deseni bir ağ modeli üzerinde göster</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Meshes (*.obj *.ply *.stl *.off *.gltf *.glb);;All files (*)</source>
        <translation>Ağ modelleri (*.obj *.ply *.stl *.off *.gltf *.glb);;Tüm dosyalar (*)</translation>
    </message>
</context>
<context>
    <name>marbler::ui::SessionStore</name>
    <message>
        <location filename="../app/workbench/SessionStore.cpp" line="+86"/>
        <source>%1 could not be moved to %2; it stays where it is</source>
        <translation>%1, %2 konumuna taşınamadı; olduğu yerde kalıyor</translation>
    </message>
</context>
<context>
    <name>marbler::ui::SessionsController</name>
    <message>
        <location filename="../app/workbench/SessionsController.cpp" line="+25"/>
        <source>&amp;New session</source>
        <translation>Yeni o&amp;turum</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start a new breeding session with a random population of the kind shown; this one stays kept under File ▸ Sessions</source>
        <translation>Gösterilen türden rastgele bir toplulukla yeni bir üretim oturumu başlat; bu oturum Dosya ▸ Oturumlar altında saklanır</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Sessions…</source>
        <translation>&amp;Oturumlar…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every breeding session is kept: resume, rename or delete one</source>
        <translation>Her üretim oturumu saklanır: birini sürdürün, yeniden adlandırın veya silin</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Resume session</source>
        <translation>Oturumu &amp;sürdür</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>A generation of the session could not be read back: %1</source>
        <translation>Oturumun bir nesli geri okunamadı: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cannot save the session</source>
        <translation>Oturum kaydedilemiyor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The breeding session could not be saved, so it would not survive a crash; keep the designs you like as favourites.

%1</source>
        <translation>Üretim oturumu kaydedilemedi, bu yüzden bir çökmeden sonra kalmaz; beğendiğiniz desenleri gözde olarak saklayın.

%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The session could not be saved: %1</source>
        <translation>Oturum kaydedilemedi: %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Cannot start a new session</source>
        <translation>Yeni oturum başlatılamıyor</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Started a new session “%1”</source>
        <translation>Yeni bir oturum başlatıldı: “%1”</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Started a new session “%1”; “%2” is kept under File ▸ Sessions</source>
        <translation>Yeni bir oturum başlatıldı: “%1”; “%2” Dosya ▸ Oturumlar altında saklanıyor</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>No other sessions</source>
        <translation>Başka oturum yok</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot resume the session</source>
        <translation>Oturum sürdürülemiyor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>There is no kept session %1 any more.</source>
        <translation>Artık saklanan bir %1 oturumu yok.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Resumed “%1” at generation %2</source>
        <translation>“%1” %2. nesilde sürdürüldü</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Resumed “%1” at generation %2; “%3” is kept under File ▸ Sessions</source>
        <translation>“%1” %2. nesilde sürdürüldü; “%3” Dosya ▸ Oturumlar altında saklanıyor</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Cannot rename the session</source>
        <translation>Oturum yeniden adlandırılamıyor</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The session being bred cannot be deleted; resume another one first</source>
        <translation>Üzerinde üretim yapılan oturum silinemez; önce başka bir oturumu sürdürün</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cannot delete the session</source>
        <translation>Oturum silinemiyor</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot bring back the session</source>
        <translation>Oturum geri getirilemiyor</translation>
    </message>
</context>
<context>
    <name>marbler::ui::SessionsDialog</name>
    <message>
        <location filename="../app/workbench/SessionsDialog.cpp" line="+25"/>
        <source>Marbler — sessions</source>
        <translation>Marbler — oturumlar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Every breeding session is kept, however Marbler was started. Resume one to go on where it was left; the one being bred stays kept.</source>
        <translation>Marbler nasıl başlatılmış olursa olsun her üretim oturumu saklanır. Kaldığı yerden devam etmek için birini sürdürün; üzerinde çalışılan oturum da saklı kalır.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Name</source>
        <translation>Ad</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Session</source>
        <translation>Oturum</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Resume</source>
        <translation>&amp;Sürdür</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Re&amp;name</source>
        <translation>Yeniden &amp;adlandır</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Delete</source>
        <translation>&amp;Sil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Undo delete</source>
        <translation>Silmeyi &amp;geri al</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Deleted “%1”. Undo delete brings it back.</source>
        <translation>“%1” silindi. Silmeyi geri al onu geri getirir.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The session is back.</source>
        <translation>Oturum geri geldi.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>being bred now — %1</source>
        <translation>şu an üretimde — %1</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>The session being bred cannot be deleted; resume another one first</source>
        <translation>Üzerinde üretim yapılan oturum silinemez; önce başka bir oturumu sürdürün</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moves the session to the trash; Undo delete brings it back</source>
        <translation>Oturumu çöpe taşır; Silmeyi geri al onu geri getirir</translation>
    </message>
</context>
<context>
    <name>marbler::ui::SolidObjectView</name>
    <message>
        <location filename="../app/editor/SolidObjectView.cpp" line="+30"/>
        <source>The design on its object: drag to turn it</source>
        <translation>Nesnesi üzerindeki desen: döndürmek için sürükleyin</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Cannot show the design on this object: %1</source>
        <translation>Desen bu nesne üzerinde gösterilemiyor: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The object the flat design is shown on, laid on its texture coordinates</source>
        <translation>Düz desenin üzerinde gösterildiği nesne; desen doku koordinatlarına yerleştirilir</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Mesh file…</source>
        <translation>Ağ dosyası…</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>The design on its object: drag to turn it; drag the block in the corner to turn the cross-section</source>
        <translation>Nesnesi üzerindeki desen: döndürmek için sürükleyin; kesiti döndürmek için köşedeki bloğu sürükleyin</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Rendering…</source>
        <translation>İşleniyor…</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>n·p = %1</source>
        <translation>n·p = %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
</context>
<context>
    <name>marbler::ui::StartDialog</name>
    <message>
        <location filename="../app/shared/StartDialog.cpp" line="+59"/>
        <source>Marbler — what to breed</source>
        <translation>Marbler — ne üretilsin</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;b&gt;What would you like to breed?&lt;/b&gt;&lt;br&gt;Nine random designs start the first generation; pick the ones you like as parents and breed the next.</source>
        <translation>&lt;b&gt;Ne üretmek istersiniz?&lt;/b&gt;&lt;br&gt;İlk nesli dokuz rastgele desen başlatır; beğendiklerinizi ebeveyn olarak seçin ve sonrakini üretin.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Breed &amp;flat (2D) designs</source>
        <translation>&amp;Düz (2B) desenler üret</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Marbled paper: patterns in the plane</source>
        <translation>Ebru kâğıdı: düzlemde desenler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Breed &amp;solid (3D) designs on an object</source>
        <translation>Bir nesne üzerinde &amp;katı (3B) desenler üret</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Marbling through a volume, shown on the object chosen beside</source>
        <translation>Bir hacmin içinden ebru; yanda seçilen nesne üzerinde gösterilir</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The object solid designs are shown on</source>
        <translation>Katı desenlerin üzerinde gösterildiği nesne</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Don&apos;t ask again (the toolbar still changes it)</source>
        <translation>&amp;Bir daha sorma (araç çubuğu yine de değiştirebilir)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> “%1”</source>
        <translation> “%1”</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Resume the last session%1 (generation %2, %3)</source>
        <translation>Son oturumu%1 &amp;sürdür (%2. nesil, %3)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>solid</source>
        <translation>katı</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>2D</source>
        <translation>2B</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Every generation of the last session, back where you left it</source>
        <translation>Son oturumun tüm nesilleri, bıraktığınız yerde</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Every session is kept; File ▸ Sessions renames and deletes them</source>
        <translation>Her oturum saklanır; Dosya ▸ Oturumlar onları yeniden adlandırır ve siler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resume &amp;another session:</source>
        <translation>&amp;Başka bir oturumu sürdür:</translation>
    </message>
</context>
<context>
    <name>marbler::ui::StatusLine</name>
    <message>
        <location filename="../app/workbench/StatusLine.cpp" line="+25"/>
        <source>What the window is doing. Help ▸ About Marbler says which renderer draws the designs.</source>
        <translation>Pencerenin ne yaptığı. Yardım ▸ Marbler hakkında desenleri hangi işleyicinin çizdiğini söyler.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Ready</source>
        <translation>Hazır</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Rendering %1 of %2…</source>
        <translation>%1 / %2 işleniyor…</translation>
    </message>
</context>
<context>
    <name>marbler::ui::StepList</name>
    <message>
        <location filename="../app/editor/StepList.cpp" line="+81"/>
        <source>Show the steps of one tool only</source>
        <translation>Yalnızca bir aracın adımlarını göster</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All steps</source>
        <translation>Tüm adımlar</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The steps of the design, first to last: the inks laid at the start, then the strokes. Drag a step to reorder; untick it to mute it; Ctrl+D duplicates, Del deletes, M mutes. A run of steps of one tool is one row: double-click it or press → to open it, ← to fold it.</source>
        <translation>Desenin ilkinden sonuncusuna adımları: başta serilen boyalar, sonra çekişler. Sırayı değiştirmek için bir adımı sürükleyin; susturmak için işaretini kaldırın; Ctrl+D çoğaltır, Del siler, M susturur. Bir aracın art arda adımları tek satırdır: açmak için çift tıklayın ya da → tuşuna, katlamak için ← tuşuna basın.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Duplicate step</source>
        <translation>Adımı &amp;çoğalt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Add a copy of the selected step after it (Ctrl+D)</source>
        <translation>Seçili adımın bir kopyasını ardına ekle (Ctrl+D)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>De&amp;lete step</source>
        <translation>Adımı &amp;sil</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Delete the selected step (Del)</source>
        <translation>Seçili adımı sil (Del)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Mute step</source>
        <translation>Adımı &amp;sustur</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Leave the selected step out of the design, or put it back (M)</source>
        <translation>Seçili adımı desenin dışında bırak ya da geri koy (M)</translation>
    </message>
    <message>
        <location line="+130"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Step %1: an ink laid at the start</source>
        <translation>Adım %1: başta serilen bir boya</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Step %1</source>
        <translation>Adım %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 %2 (steps %3–%4)</source>
        <translation>%1 %2 (%3–%4. adımlar)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Steps %1–%2: %3 %4, shown as one row (double-click or press → to see them); selecting it selects step %1, its box mutes them all</source>
        <translation>%1–%2. adımlar: %3 %4, tek satır olarak gösteriliyor (görmek için çift tıklayın ya da → tuşuna basın); seçmek %1. adımı seçer, kutusu hepsini susturur</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The first of %1 %2 (double-click or press ← to fold them)</source>
        <translation>%1 %2 içinden ilki (katlamak için çift tıklayın ya da ← tuşuna basın)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Muted: left out of the design (tick to put it back)</source>
        <translation>Susturuldu: desenin dışında bırakıldı (geri koymak için işaretleyin)</translation>
    </message>
    <message>
        <location line="+90"/>
        <source>&amp;Fold the group (←)</source>
        <translation>Grubu &amp;katla (←)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Open the group (→)</source>
        <translation>Grubu &amp;aç (→)</translation>
    </message>
</context>
<context>
    <name>marbler::ui::Timeline</name>
    <message>
        <location filename="../app/editor/Timeline.cpp" line="+45"/>
        <source>&amp;Compare</source>
        <translation>&amp;Karşılaştır</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The making of the design: drag to see it after any step, part way through a step (0: the bare bath; the right end: the whole design)</source>
        <translation>Desenin yapılışı: onu herhangi bir adımdan sonra ya da bir adımın ortasında görmek için sürükleyin (0: boş tekne; sağ uç: desenin tamamı)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The second state compared side by side with the first</source>
        <translation>İlkiyle yan yana karşılaştırılan ikinci durum</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+123"/>
        <source>Play</source>
        <translation>Oynat</translation>
    </message>
    <message>
        <location line="-121"/>
        <source>Play the making of the design, each step growing in; again to stop</source>
        <translation>Desenin yapılışını oynat, her adım belirerek gelir; durdurmak için yine basın</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Compare two states of the making side by side: the second slider picks the other</source>
        <translation>Yapılışın iki durumunu yan yana karşılaştır: ikinci kaydırıcı ötekini seçer</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Play speed: 1× plays the whole making in at most 12 s (0.6 s a step); faster for a quick look, slower to watch each step ([ and ])</source>
        <translation>Oynatma hızı: 1× yapılışın tamamını en çok 12 sn&apos;de oynatır (adım başına 0,6 sn); hızlı bir bakış için daha hızlı, her adımı izlemek için daha yavaş ([ ve ])</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export animation…</source>
        <translation>Animasyonu dışa aktar…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write the making of the design as a video, an animated image or PNG frames</source>
        <translation>Desenin yapılışını video, hareketli görüntü ya da PNG kareleri olarak yaz</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The step shown, of all the design&apos;s steps</source>
        <translation>Desenin tüm adımları içinde gösterilen adım</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Play slower</source>
        <translation>Daha yavaş oynat</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Play faster</source>
        <translation>Daha hızlı oynat</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Stop</source>
        <translation>Durdur</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Now</source>
        <translation>Şimdi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bare bath</source>
        <translation>Boş tekne</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step %1 of %2</source>
        <translation>Adım %1 / %2</translation>
    </message>
</context>
<context>
    <name>marbler::ui::ToolOptions</name>
    <message>
        <location filename="../app/editor/ToolOptions.cpp" line="+46"/>
        <source>Pick</source>
        <translation>Seç</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Line of drops</source>
        <translation>Damla dizisi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rings</source>
        <translation>Halkalar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Scatter</source>
        <translation>Saçma</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Click to pick the ink there and select the step that laid it</source>
        <translation>Oradaki boyayı seçmek ve onu seren adımı seçmek için tıklayın</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Drag to lay a line of drops from the press to the release</source>
        <translation>Basılan yerden bırakılan yere bir damla dizisi sermek için sürükleyin</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Drag from the centre: concentric rings out to the release</source>
        <translation>Merkezden sürükleyin: bırakılan yere kadar iç içe halkalar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Drag from the centre: drops scattered evenly in the circle</source>
        <translation>Merkezden sürükleyin: dairenin içine eşit serpilmiş damlalar</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>The palette ink the tool lays</source>
        <translation>Aracın serdiği palet boyası</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Ink</source>
        <translation>Boya</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A clicked drop&apos;s radius (a drag sets it)</source>
        <translation>Tıklanan bir damlanın yarıçapı (sürükleme onu belirler)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Droplet</source>
        <translation>Damlacık</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The radius of each sprayed droplet</source>
        <translation>Püskürtülen her damlacığın yarıçapı</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Droplets</source>
        <translation>Damlacıklar</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>How many droplets one stroke sprinkles</source>
        <translation>Bir çekişin kaç damlacık serptiği</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Brush</source>
        <translation>Fırça</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>How far from the stroke droplets land</source>
        <translation>Damlacıkların çekişten ne kadar uzağa düştüğü</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Drops</source>
        <translation>Damlalar</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>How many drops the pattern lays</source>
        <translation>Düzenin kaç damla serdiği</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The distance between the comb&apos;s tines</source>
        <translation>Tarağın dişleri arasındaki uzaklık</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The length of one period of the wave</source>
        <translation>Dalganın bir periyodunun uzunluğu</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>How far the circle moves the ink along its rim (a vortex&apos;s click too)</source>
        <translation>Dairenin boyayı çemberi boyunca ne kadar götürdüğü (girdap tıklaması da)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Smaller concentrates the shift near the stroke</source>
        <translation>Daha küçüğü kaymayı çekişin yakınında toplar</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A finite centre: 0 winds without end, larger keeps the eye clean</source>
        <translation>Sonlu bir merkez: 0 sonsuzca sarar, daha büyüğü gözü temiz tutar</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>across the section</source>
        <translation>kesite dik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The axis a solid&apos;s circle or sphere turns about, as x, y, z (e.g. 0, 1, 1); empty: across the section it is drawn on</source>
        <translation>Katı bir desende daire veya kürenin döndüğü eksen, x, y, z olarak (ör. 0, 1, 1); boş: çizildiği kesite dik</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Axis</source>
        <translation>Eksen</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Teeth</source>
        <translation>Dişler</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>How many teeth span the design</source>
        <translation>Deseni kaç dişin kapladığı</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The tooth profile |sin|^p: small is blunt, large is pointed</source>
        <translation>Diş profili |sin|^p: küçüğü küt, büyüğü sivri</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cells</source>
        <translation>Hücreler</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cavity</source>
        <translation>Oyuk</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The velocity field: a lattice of cells or one cavity</source>
        <translation>Hız alanı: bir hücre örgüsü ya da tek bir oyuk</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The flow&apos;s speed; its sign is the sense of turning</source>
        <translation>Akışın hızı; işareti dönüş yönüdür</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>How long the flow runs</source>
        <translation>Akışın ne kadar sürdüğü</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>How hard the stylus pulls the ink along its path: about the shift on the track; negative pushes it back</source>
        <translation>Bizin boyayı izi boyunca ne kadar güçlü çektiği: aşağı yukarı iz üzerindeki kayma; eksi değer geri iter</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>How far to the side of the track the pull reaches: smaller is a finer line</source>
        <translation>Çekişin izin yanına ne kadar eriştiği: daha küçüğü daha ince bir çizgidir</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>How far ahead of and behind the stylus the bath moves</source>
        <translation>Teknenin bizin ne kadar önünde ve arkasında hareket ettiği</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>1 draws with a single stylus; more draws a rake of that many tines</source>
        <translation>1 tek bir bizle çizer; daha çoğu o kadar dişli bir tarakla çizer</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The distance between the rake&apos;s tines (with more than one)</source>
        <translation>Tarağın dişleri arasındaki uzaklık (birden çok diş varken)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Seed</source>
        <translation>Tohum</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where sprayed and scattered drops land: the same seed, the same drops</source>
        <translation>Püskürtülen ve serpilen damlaların düştüğü yer: aynı tohum, aynı damlalar</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>Ink %1</source>
        <translation>Boya %1</translation>
    </message>
    <message>
        <location filename="registry-words.cpp" line="-150"/>
        <source>Drop</source>
        <translation>Damla</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Click to drop ink of the current colour; drag to set its radius. A drop in a drop pushes the older ink into a ring</source>
        <translation>Geçerli renkte boya damlatmak için tıklayın; yarıçapını belirlemek için sürükleyin. Damla içine damla, eski boyayı bir halkaya iter</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spray</source>
        <translation>Serpme</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag a brush that sprinkles small droplets along its path</source>
        <translation>Yolu boyunca küçük damlacıklar serpen bir fırçayı sürükleyin</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Line</source>
        <translation>Çizgi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag a stylus through the ink: the drag&apos;s direction and length</source>
        <translation>Boyanın içinden bir biz sürükleyin: sürüklemenin yönü ve uzunluğu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Comb</source>
        <translation>Tarak</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag a comb through the ink: the drag&apos;s direction and length</source>
        <translation>Boyanın içinden bir tarak sürükleyin: sürüklemenin yönü ve uzunluğu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wave</source>
        <translation>Dalga</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag a wavy comb: the drag gives its direction and amplitude</source>
        <translation>Dalgalı bir tarak sürükleyin: sürükleme yönünü ve genliğini verir</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Circle</source>
        <translation>Daire</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag from the centre: a circular stroke of that radius</source>
        <translation>Merkezden sürükleyin: o yarıçapta dairesel bir çekiş</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sphere</source>
        <translation>Küre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag from the centre on the section: a tine moved round a sphere of that radius, turning about the panel&apos;s axis</source>
        <translation>Kesit üzerinde merkezden sürükleyin: o yarıçapta bir kürenin çevresinde, panelin ekseni etrafında dönen bir diş</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Vortex</source>
        <translation>Girdap</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag from the centre: a swirl, the drag&apos;s length its strength</source>
        <translation>Merkezden sürükleyin: bir girdap; sürüklemenin uzunluğu gücüdür</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stretch</source>
        <translation>Germe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag to stretch the ink between teeth across the design</source>
        <translation>Boyayı desen boyunca dişler arasında germek için sürükleyin</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Flow</source>
        <translation>Akış</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag out a cell of a steady flow (cells or one cavity)</source>
        <translation>Durağan bir akışın bir hücresini sürükleyerek çizin (hücreler ya da tek oyuk)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stylus</source>
        <translation>Biz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Draw a free-hand stroke: a stylus (or a rake) pulled along the path</source>
        <translation>Serbest elle bir çekiş çizin: yol boyunca çekilen bir biz (ya da tarak)</translation>
    </message>
</context>
<context>
    <name>marbler::ui::WorkbenchWindow</name>
    <message>
        <location filename="../app/workbench/SessionsController.cpp" line="+20"/>
        <source>Cannot resume the last session</source>
        <translation>Son oturum sürdürülemiyor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The session could not be read, so it is not resumed.

%1

%2</source>
        <translation>Oturum okunamadı, bu yüzden sürdürülmüyor.

%1

%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The file could not be moved aside.</source>
        <translation>Dosya kenara taşınamadı.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The file is kept as %1.</source>
        <translation>Dosya %1 olarak saklanıyor.</translation>
    </message>
    <message>
        <location filename="../app/workbench/Workbench.cpp" line="+156"/>
        <source>Cannot move the saved sessions</source>
        <translation>Kaydedilmiş oturumlar taşınamıyor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sessions saved by an earlier Marbler could not be moved into the list of kept sessions; they are left where they are.

%1</source>
        <translation>Marbler&apos;ın önceki bir sürümünün kaydettiği oturumlar saklanan oturumlar listesine taşınamadı; oldukları yerde bırakıldılar.

%1</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>Started a new session; your previous session “%1” is kept under File ▸ Sessions</source>
        <translation>Yeni bir oturum başlatıldı; önceki oturumunuz “%1” Dosya ▸ Oturumlar altında saklanıyor</translation>
    </message>
    <message>
        <location filename="../app/workbench/WorkbenchEditor.cpp" line="+43"/>
        <source>“%1” is open in an editor already</source>
        <translation>“%1” zaten bir düzenleyicide açık</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>From the editor: %1</source>
        <translation>Düzenleyiciden: %1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Recovered “%1”</source>
        <translation>“%1” kurtarıldı</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Recover a design</source>
        <translation>Bir deseni kurtar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Marbler stopped before the changes to “%1” were saved (autosaved %2). Open them in the editor?

If not, they are kept for %3 days under File ▸ Recover unsaved designs….</source>
        <translation>Marbler, “%1” üzerindeki değişiklikler kaydedilmeden durdu (otomatik kayıt: %2). Düzenleyicide açılsınlar mı?

Açılmazlarsa %3 gün boyunca Dosya ▸ Kaydedilmemiş desenleri kurtar… altında saklanırlar.</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Recover unsaved designs</source>
        <translation>Kaydedilmemiş desenleri kurtar</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Designs that editors left unsaved when Marbler stopped. Each is kept for %1 days after its last autosave, until you open or discard it.</source>
        <translation>Marbler durduğunda düzenleyicilerin kaydetmeden bıraktığı desenler. Her biri son otomatik kaydından sonra %1 gün, siz açana ya da atana dek saklanır.</translation>
    </message>
    <message>
        <location line="+10"/>
        <location filename="../app/workbench/WorkbenchWindow.cpp" line="+984"/>
        <source>Open in editor</source>
        <translation>Düzenleyicide aç</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Discard…</source>
        <translation>At…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 — autosaved %2</source>
        <translation>%1 — otomatik kayıt %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Nothing to recover</source>
        <translation>Kurtarılacak bir şey yok</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Discard a design</source>
        <translation>Bir deseni at</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Discard the unsaved changes to “%1” for good?</source>
        <translation>“%1” üzerindeki kaydedilmemiş değişiklikler kalıcı olarak atılsın mı?</translation>
    </message>
    <message>
        <location filename="../app/workbench/WorkbenchGuide.cpp" line="+13"/>
        <source>&lt;h2&gt;Marbler guide&lt;/h2&gt;&lt;p&gt;The grid shows nine designs: one &lt;i&gt;generation&lt;/i&gt;. Breed the next one from the designs you like.&lt;/p&gt;&lt;h3&gt;Pick parents&lt;/h3&gt;&lt;p&gt;Click a design to pick it as a parent (it gets a frame); click it again to let it go. With the keyboard, the arrows move between designs and Space picks. %1 (%2) lets every parent go. Parents stay in their cells; every other cell gets offspring.&lt;/p&gt;&lt;h3&gt;Breed&lt;/h3&gt;&lt;p&gt;Apply an operator from the Breed menu or the toolbar:&lt;/p&gt;&lt;ul&gt;</source>
        <translation>&lt;h2&gt;Marbler kılavuzu&lt;/h2&gt;&lt;p&gt;Izgara dokuz desen gösterir: bir &lt;i&gt;nesil&lt;/i&gt;. Sonrakini beğendiğiniz desenlerden üretin.&lt;/p&gt;&lt;h3&gt;Ebeveyn seçin&lt;/h3&gt;&lt;p&gt;Bir deseni ebeveyn olarak seçmek için ona tıklayın (çerçeve alır); bırakmak için yeniden tıklayın. Klavyeyle oklar desenler arasında gezer, Boşluk seçer. %1 (%2) tüm ebeveynleri bırakır. Ebeveynler hücrelerinde kalır; diğer her hücreye yavru gelir.&lt;/p&gt;&lt;h3&gt;Üretin&lt;/h3&gt;&lt;p&gt;Üret menüsünden ya da araç çubuğundan bir işlem uygulayın:&lt;/p&gt;&lt;ul&gt;</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&lt;/ul&gt;&lt;p&gt;The &lt;b&gt;Strength&lt;/b&gt; slider beside them sets how far %1 moves the strokes, from 0 % (barely) to 100 % (a lot). An operator that cannot run is greyed out; its tooltip says what it needs. Flat (2D) and solid (3D) designs do not breed together.&lt;/p&gt;</source>
        <translation>&lt;/ul&gt;&lt;p&gt;Yanlarındaki &lt;b&gt;Güç&lt;/b&gt; kaydırıcısı %1 işleminin çekişleri ne kadar oynattığını belirler: yüzde 0 (pek az) ile yüzde 100 (çok) arasında. Çalışamayan bir işlem soluk görünür; araç ipucu neye ihtiyaç duyduğunu söyler. Düz (2B) ve katı (3B) desenler birlikte üretilmez.&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&lt;h3&gt;Back and forward&lt;/h3&gt;&lt;p&gt;Every change (breeding, a new random population, opening designs, bringing back a favourite) is a new generation, and nothing is lost: &lt;b&gt;%1&lt;/b&gt; (%2) and &lt;b&gt;%3&lt;/b&gt; (%4) step through them. The Lineage panel lists every generation; double-click one to go to it.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Geri ve ileri&lt;/h3&gt;&lt;p&gt;Her değişiklik (üretim, yeni bir rastgele topluluk, desen açma, bir gözdeyi geri getirme) yeni bir nesildir ve hiçbir şey kaybolmaz: &lt;b&gt;%1&lt;/b&gt; (%2) ve &lt;b&gt;%3&lt;/b&gt; (%4) nesiller arasında gezer. Soy paneli tüm nesilleri listeler; birine gitmek için çift tıklayın.&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&lt;h3&gt;Favourites&lt;/h3&gt;&lt;p&gt;Press F on a design (or right-click it, &lt;i&gt;Keep as favourite&lt;/i&gt;) to keep it on the Favourites shelf, where it is saved as a genome file. Double-click a favourite, or drag it onto a cell, to bring it back.&lt;/p&gt;&lt;h3&gt;The large view&lt;/h3&gt;&lt;p&gt;Double-click a design, or press Enter on it, to see it large. Drag a solid design to turn its object. &lt;i&gt;Save genome…&lt;/i&gt; (%1) writes the design&apos;s genome file; &lt;i&gt;Export image…&lt;/i&gt; (%2) renders it to PNG, TIFF, EXR or JPEG at any size; a PNG or TIFF carries the design&apos;s genome, so it opens again as a design. &lt;i&gt;Copy genome&lt;/i&gt; (%3) puts the genome on the clipboard as text. The status bar then says where the file went, with &lt;i&gt;Show in folder&lt;/i&gt;.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Gözdeler&lt;/h3&gt;&lt;p&gt;Bir deseni Gözdeler rafında saklamak için üzerinde F tuşuna basın (ya da sağ tıklayıp &lt;i&gt;Gözde olarak sakla&lt;/i&gt;&apos;yı seçin); orada bir genom dosyası olarak kaydedilir. Geri getirmek için bir gözdeye çift tıklayın ya da onu bir hücreye sürükleyin.&lt;/p&gt;&lt;h3&gt;Büyük görünüm&lt;/h3&gt;&lt;p&gt;Bir deseni büyük görmek için ona çift tıklayın ya da üzerinde Enter&apos;a basın. Katı bir desenin nesnesini döndürmek için sürükleyin. &lt;i&gt;Genomu kaydet…&lt;/i&gt; (%1) desenin genom dosyasını yazar; &lt;i&gt;Görüntüyü dışa aktar…&lt;/i&gt; (%2) onu istenen boyutta PNG, TIFF, EXR veya JPEG olarak işler; PNG veya TIFF desenin genomunu taşır, böylece yeniden desen olarak açılır. &lt;i&gt;Genomu kopyala&lt;/i&gt; (%3) genomu metin olarak panoya koyar. Ardından durum çubuğu dosyanın nereye gittiğini &lt;i&gt;Klasörde göster&lt;/i&gt; ile birlikte söyler.&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>&lt;h3&gt;Opening designs&lt;/h3&gt;&lt;p&gt;File ▸ Open designs, or drop genome files on the window (or PNG and TIFF images Marbler exported, which carry their genomes; a plain image is refused): they go into the selected cells, then free ones. &lt;b&gt;%1&lt;/b&gt; (%2) copies the focused or selected design as genome text, and &lt;b&gt;%3&lt;/b&gt; (%4) puts a genome from the clipboard into the grid the same way. When they would replace designs you are asked whether to replace the selected cells or add them as a new generation that keeps the parents. Dropped on a cell, a file replaces that cell (a parent only after asking). A flat design opened among solid ones (or the reverse) starts a generation of its own kind, since the two kinds cannot breed together; the grid it replaces is one generation back.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Desen açma&lt;/h3&gt;&lt;p&gt;Dosya ▸ Desenleri aç&apos;ı kullanın ya da genom dosyalarını pencereye bırakın (veya Marbler&apos;ın dışa aktardığı, genomlarını taşıyan PNG ve TIFF görüntülerini; sıradan bir görüntü reddedilir): önce seçili hücrelere, sonra boş olanlara giderler. &lt;b&gt;%1&lt;/b&gt; (%2) odaktaki ya da seçili deseni genom metni olarak kopyalar, &lt;b&gt;%3&lt;/b&gt; (%4) panodaki bir genomu ızgaraya aynı şekilde koyar. Desenlerin yerine geçeceklerse, seçili hücrelerin yerine mi konacakları yoksa ebeveynleri koruyan yeni bir nesil olarak mı eklenecekleri sorulur. Bir hücreye bırakılan dosya o hücrenin yerine geçer (ebeveynse ancak sorduktan sonra). Katı desenler arasında açılan düz bir desen (ya da tersi) kendi türünden bir nesil başlatır, çünkü iki tür birlikte üretilemez; yerine geçtiği ızgara bir nesil geride kalır.&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&lt;h3&gt;Keyboard&lt;/h3&gt;&lt;p&gt;On a design in the grid: the arrows move, Space picks or lets go, Enter opens it large, F keeps it as a favourite, the Menu key opens its menu.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Klavye&lt;/h3&gt;&lt;p&gt;Izgaradaki bir desen üzerinde: oklar gezer, Boşluk seçer ya da bırakır, Enter büyük açar, F gözde olarak saklar, Menü tuşu menüsünü açar.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/workbench/WorkbenchPicture.cpp" line="+15"/>
        <location line="+21"/>
        <source>Cannot marble the picture</source>
        <translation>Resim ebrulanamıyor</translation>
    </message>
    <message>
        <location line="-20"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no such file</source>
        <translation>böyle bir dosya yok</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 marbled %2</source>
        <translation>%1 ebrulandı %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Marbled %1</source>
        <translation>%1 ebrulandı</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Marble a picture</source>
        <translation>Bir resmi ebrula</translation>
    </message>
    <message>
        <location filename="../app/workbench/WorkbenchWindow.cpp" line="-904"/>
        <source>Marbler designs (*.marble.json *.json *.png *.tif *.tiff);;Genome files (*.marble.json *.json);;Images with a genome (*.png *.tif *.tiff);;All files (*)</source>
        <translation>Marbler desenleri (*.marble.json *.json *.png *.tif *.tiff);;Genom dosyaları (*.marble.json *.json);;Genom taşıyan görüntüler (*.png *.tif *.tiff);;Tüm dosyalar (*)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Marbler — evolution workbench</source>
        <translation>Marbler — evrim tezgâhı</translation>
    </message>
    <message>
        <location line="+24"/>
        <location line="+845"/>
        <source>Brought back a favourite</source>
        <translation>Bir gözde geri getirildi</translation>
    </message>
    <message>
        <location line="-843"/>
        <source>Cannot use the dropped design</source>
        <translation>Bırakılan desen kullanılamıyor</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>Cannot show the mesh</source>
        <translation>Ağ modeli gösterilemiyor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1

The designs are shown on the %2 instead.</source>
        <translation>%1

Desenler bunun yerine %2 üzerinde gösteriliyor.</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Some favourites could not be read: %1</source>
        <translation>Bazı gözdeler okunamadı: %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&amp;File</source>
        <translation>&amp;Dosya</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Edit</source>
        <translation>Dü&amp;zen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Breed</source>
        <translation>Ü&amp;ret</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;View</source>
        <translation>&amp;Görünüm</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Breeding</source>
        <translation>Üretim</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Open designs…</source>
        <translation>Desenleri &amp;aç…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Load genome files, or PNG and TIFF images Marbler wrote, into the selected cells, then free ones; asks before replacing designs</source>
        <translation>Genom dosyalarını ya da Marbler&apos;ın yazdığı PNG ve TIFF görüntülerini önce seçili hücrelere, sonra boş olanlara yükle; desenlerin yerine koymadan önce sorar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>New &amp;design</source>
        <translation>Yeni &amp;desen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Blank &amp;flat bath</source>
        <translation>Boş &amp;düz tekne</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Make a flat design by hand in the editor, from a bare bath</source>
        <translation>Düzenleyicide boş bir tekneden elle düz bir desen yap</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Blank &amp;solid block</source>
        <translation>Boş &amp;katı blok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Make a solid design by hand in the editor, from a bare block</source>
        <translation>Düzenleyicide boş bir bloktan elle katı bir desen yap</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Random design</source>
        <translation>&amp;Rastgele desen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A random design of the kind chosen on the tool bar, to edit by hand</source>
        <translation>Araç çubuğunda seçilen türden, elle düzenlenecek rastgele bir desen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open in &amp;editor…</source>
        <translation>&amp;Düzenleyicide aç…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open a design in the editor</source>
        <translation>Düzenleyicide bir desen aç</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cannot open the design</source>
        <translation>Desen açılamıyor</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Edit a genome file, or an image carrying a genome, step by step</source>
        <translation>Bir genom dosyasını ya da genom taşıyan bir görüntüyü adım adım düzenle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New random population</source>
        <translation>&amp;Yeni rastgele topluluk</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>New random</source>
        <translation>Yeni rastgele</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nine new random designs of the kind chosen beside (Ctrl+N)</source>
        <translation>Yanda seçilen türden dokuz yeni rastgele desen (Ctrl+N)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Marble a picture…</source>
        <translation>Bir resmi &amp;ebrula…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Nine flat designs whose bath is a picture you pick: flows and strokes carry its colours</source>
        <translation>Teknesi seçtiğiniz bir resim olan dokuz düz desen: akışlar ve çekişler onun renklerini taşır</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>A procedural marbled paper (as marbler paper makes) into the grid, to breed from</source>
        <translation>Üretmek için ızgaraya, yordamsal bir ebru kâğıdı (marbler paper&apos;ın yaptığı gibi)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Quit</source>
        <translation>Çı&amp;k</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Back a generation</source>
        <translation>Bir nesil &amp;geri</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>◀ Back</source>
        <translation>◀ Geri</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Back to the generation this one grew from (Ctrl+Z)</source>
        <translation>Bu neslin çıktığı nesle geri dön (Ctrl+Z)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Forward a generation</source>
        <translation>Bir nesil &amp;ileri</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Forward ▶</source>
        <translation>İleri ▶</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Forward to the generation last visited or made from this one (Ctrl+Shift+Z)</source>
        <translation>Son ziyaret edilen ya da bundan yapılan nesle ilerle (Ctrl+Shift+Z)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Copy design</source>
        <translation>Deseni &amp;kopyala</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Copies the focused design (else the first selected one) as genome text</source>
        <translation>Odaktaki deseni (yoksa ilk seçileni) genom metni olarak kopyalar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Paste design</source>
        <translation>Deseni &amp;yapıştır</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Puts the genome on the clipboard into the grid, as File ▸ Open does</source>
        <translation>Panodaki genomu, Dosya ▸ Aç gibi ızgaraya koyar</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Clear &amp;selection</source>
        <translation>&amp;Seçimi temizle</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&amp;Wildcard cell</source>
        <translation>&amp;Joker hücre</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The last offspring cell of each generation is a fresh design of the parents&apos; family</source>
        <translation>Her neslin son yavru hücresi, ebeveynlerin ailesinden taze bir desendir</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>New population</source>
        <translation>Yeni topluluk</translation>
    </message>
    <message>
        <location line="+143"/>
        <source>%1 · less like this</source>
        <translation>%1 · bunun gibi daha az</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>No designs yet: make a new random population (Ctrl+N) or open designs (Ctrl+O)</source>
        <translation>Henüz desen yok: yeni bir rastgele topluluk yapın (Ctrl+N) ya da desen açın (Ctrl+O)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Generation %1: %2 — %3 selected</source>
        <translation>%1. nesil: %2 — %3 seçili</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>1 parent</source>
        <translation>1 ebeveyn</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 parents</source>
        <translation>%1 ebeveyn</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> — %1</source>
        <translation> — %1</translation>
    </message>
    <message>
        <location line="+102"/>
        <source>Design %1 cannot be rendered: %2</source>
        <translation>Desen %1 işlenemiyor: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>An empty cell: open a design (Ctrl+O) or drop a file here</source>
        <translation>Boş bir hücre: bir desen açın (Ctrl+O) ya da buraya bir dosya bırakın</translation>
    </message>
    <message>
        <location line="+38"/>
        <location line="+17"/>
        <source>Cannot breed</source>
        <translation>Üretilemiyor</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>Breeding generation %1…</source>
        <translation>%1. nesil üretiliyor…</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Breeding cancelled: the generation is as it was</source>
        <translation>Üretim iptal edildi: nesil olduğu gibi kaldı</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Bred generation %1 with %2</source>
        <translation>%1. nesil %2 ile üretildi</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Cannot make a random population</source>
        <translation>Rastgele topluluk yapılamıyor</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Cannot open a design</source>
        <translation>Bir desen açılamıyor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>These files could not be loaded; the population is unchanged by them.

%1</source>
        <translation>Bu dosyalar yüklenemedi; topluluk onlardan etkilenmedi.

%1</translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+143"/>
        <source>design %1</source>
        <translation>desen %1</translation>
    </message>
    <message>
        <location line="-652"/>
        <source>New marbled &amp;paper…</source>
        <translation>Yeni e&amp;bru kâğıdı…</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>&amp;Rename…</source>
        <translation>Yeniden &amp;adlandır…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Names the focused design (else the first selected one) and gives it a note</source>
        <translation>Odaktaki desene (yoksa ilk seçilene) bir ad ve bir not verir</translation>
    </message>
    <message>
        <location line="+453"/>
        <source>Nothing opened: %1 holds no design</source>
        <translation>Hiçbir şey açılmadı: %1 desen içermiyor</translation>
    </message>
    <message>
        <location line="+33"/>
        <location line="+1"/>
        <location line="+75"/>
        <source>solid</source>
        <translation>katı</translation>
    </message>
    <message>
        <location line="-76"/>
        <location line="+1"/>
        <location line="+75"/>
        <source>flat</source>
        <translation>düz</translation>
    </message>
    <message>
        <location line="-74"/>
        <location line="+12"/>
        <source>Opened %1</source>
        <translation>%1 açıldı</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>Opened %1 and %2: the %3 designs are a generation of their own, the %4 ones one generation back (%5)</source>
        <translation>%1 ve %2 açıldı: %3 desenler kendi başına bir nesil oldu, %4 olanlar bir nesil geride (%5)</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Nothing opened: the grid is as it was</source>
        <translation>Hiçbir şey açılmadı: ızgara olduğu gibi</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: only %2 of %3 designs found room in the grid</source>
        <translation>%1: %3 desenden yalnızca %2 tanesi ızgarada yer buldu</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1: %2 designs start a generation of their own; the %3 designs are one generation back (%4)</source>
        <translation>%1: %2 desenler kendi nesillerini başlatıyor; %3 desenler bir nesil geride (%4)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1; the grid before is one generation back (%2)</source>
        <translation>%1; önceki ızgara bir nesil geride (%2)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Open designs</source>
        <translation>Desenleri aç</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Nothing copied: click or select a design first</source>
        <translation>Hiçbir şey kopyalanmadı: önce bir desene tıklayın ya da seçin</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+268"/>
        <source>Copied %1 to the clipboard as genome text</source>
        <translation>%1 panoya genom metni olarak kopyalandı</translation>
    </message>
    <message>
        <location line="-253"/>
        <source>Cannot make the paper</source>
        <translation>Kâğıt yapılamıyor</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Marbled paper %1 (seed %2)</source>
        <translation>Ebru kâğıdı %1 (tohum %2)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Nothing pasted: the clipboard holds no Marbler design (%1)</source>
        <translation>Hiçbir şey yapıştırılmadı: panoda Marbler deseni yok (%1)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Pasted %1</source>
        <translation>%1 yapıştırıldı</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Open a design here…</source>
        <translation>Buraya bir desen aç…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open a design</source>
        <translation>Bir desen aç</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Deselect parent</source>
        <translation>Ebeveyn seçimini kaldır</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Select as parent</source>
        <translation>Ebeveyn olarak seç</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>More like this</source>
        <translation>Bunun gibi daha fazla</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Breeds the next generation from this design alone</source>
        <translation>Sonraki nesli yalnızca bu desenden üretir</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No longer less like this</source>
        <translation>Artık bunun gibi daha az değil</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Less like this</source>
        <translation>Bunun gibi daha az</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Steering moves the next generations away from this design</source>
        <translation>Yönlendirme sonraki nesilleri bu desenden uzaklaştırır</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open large…</source>
        <translation>Büyük aç…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Keep as favourite</source>
        <translation>Gözde olarak sakla</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rename…</source>
        <translation>Yeniden adlandır…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save design…</source>
        <translation>Deseni kaydet…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy design</source>
        <translation>Deseni kopyala</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Lock palette</source>
        <translation>Paleti kilitle</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Operators keep this design&apos;s inks</source>
        <translation>İşlemler bu desenin boyalarını korur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lock initial state</source>
        <translation>Başlangıcı kilitle</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Operators keep this design&apos;s initial drops</source>
        <translation>İşlemler bu desenin ilk damlalarını korur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lock operations</source>
        <translation>Çekişleri kilitle</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Operators keep this design&apos;s strokes</source>
        <translation>İşlemler bu desenin çekişlerini korur</translation>
    </message>
    <message>
        <location line="+120"/>
        <source>Nothing to rename: click or select a design first</source>
        <translation>Yeniden adlandırılacak bir şey yok: önce bir desene tıklayın ya da bir desen seçin</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Renamed design %1 to “%2”</source>
        <translation>Desen %1, “%2” olarak yeniden adlandırıldı</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Renamed design %1 to “%2”: another design of this session is called “%3”</source>
        <translation>Desen %1, “%2” olarak yeniden adlandırıldı: bu oturumdaki başka bir desenin adı da “%3”</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>design %1 of generation %2</source>
        <translation>%2. neslin %1. deseni</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+3"/>
        <source>Brought back %1</source>
        <translation>%1 geri getirildi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Brought back %1 into design %2</source>
        <translation>%1, desen %2 yerine geri getirildi</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Resumed the last session at generation %1</source>
        <translation>Son oturum %1. nesilde sürdürüldü</translation>
    </message>
</context>
</TS>
