<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>Lineage</name>
    <message>
        <location filename="../app/shared/Lineage.cpp" line="+41"/>
        <source>(not bred)</source>
        <translation>(nicht gezüchtet)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1, varied</source>
        <translation>%1, abgewandelt</translation>
    </message>
</context>
<context>
    <name>MeshChooser</name>
    <message>
        <location filename="../app/shared/MeshChooser.cpp" line="+27"/>
        <source>Show the designs on a mesh</source>
        <translation>Muster auf einem Mesh zeigen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Meshes (*.obj *.stl *.ply *.gltf *.glb *.off);;All files (*)</source>
        <translation>Meshes (*.obj *.stl *.ply *.gltf *.glb *.off);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>QMessageBox</name>
    <message>
        <location filename="../app/shared/Language.cpp" line="+48"/>
        <source>Show Details...</source>
        <translation>Details anzeigen...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hide Details...</source>
        <translation>Details ausblenden...</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <location filename="../app/editor/Recovery.cpp" line="+140"/>
        <source>A recovery file was skipped: %1</source>
        <translation>Eine Wiederherstellungsdatei wurde übersprungen: %1</translation>
    </message>
    <message>
        <location filename="../app/shared/BackgroundJob.cpp" line="+36"/>
        <source>an unknown error</source>
        <translation>ein unbekannter Fehler</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../app/shared/BakeObject.cpp" line="+28"/>
        <source>Baking %1…</source>
        <translation>%1 wird gebacken…</translation>
    </message>
    <message>
        <location line="+30"/>
        <location line="+13"/>
        <location line="+18"/>
        <source>Cannot bake onto the object</source>
        <translation>Backen auf das Objekt nicht möglich</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&amp;Bake onto object</source>
        <translation>Auf Objekt &amp;backen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Write the object with the design baked into its texture, following the object&apos;s texture coordinates, for other 3D tools (glTF .glb or .gltf, OBJ; a %1 × %1 texture)</source>
        <translation>Das Objekt mit dem entlang seiner Texturkoordinaten in seine Textur gebackenen Muster für andere 3D-Werkzeuge schreiben (glTF .glb oder .gltf, OBJ; eine %1 × %1-Textur)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The object shown (%1)…</source>
        <translation>Das gezeigte Objekt (%1)…</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Mesh file…</source>
        <translation>&amp;Mesh-Datei…</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Bake onto object…</source>
        <translation>Auf Objekt &amp;backen…</translation>
    </message>
    <message>
        <location line="-57"/>
        <source>Bake onto object</source>
        <translation>Auf Objekt backen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>3D objects (*.glb *.gltf *.obj)</source>
        <translation>3D-Objekte (*.glb *.gltf *.obj)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: choose .glb, .gltf or .obj</source>
        <translation>%1: wählen Sie .glb, .gltf oder .obj</translation>
    </message>
    <message>
        <location filename="../app/shared/DesignDialog.cpp" line="+423"/>
        <source>Save design</source>
        <translation>Muster speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Marbler genomes (*.marble.json)</source>
        <translation>Marbler-Genome (*.marble.json)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cannot save the design</source>
        <translation>Das Muster kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location filename="../app/shared/ExportSettingsDialog.cpp" line="+49"/>
        <source>Off (1 sample, fastest)</source>
        <translation>Aus (1 Abtastung, am schnellsten)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One sample a pixel: hard, stepped edges</source>
        <translation>Eine Abtastung je Pixel: harte, gestufte Kanten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Smooth (4 samples, default)</source>
        <translation>Glatt (4 Abtastungen, Standard)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Four samples a pixel on a rotated grid: smooth edges at a small cost</source>
        <translation>Vier Abtastungen je Pixel auf einem gedrehten Raster: glatte Kanten bei geringem Aufwand</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Soft (5 samples)</source>
        <translation>Weich (5 Abtastungen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Five samples a pixel, the centre weighted most: slightly soft edges</source>
        <translation>Fünf Abtastungen je Pixel, die Mitte am stärksten gewichtet: leicht weiche Kanten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fine checkerboard (%1 samples)</source>
        <translation>Feines Schachbrett (%1 Abtastungen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Samples on every other square of a 4 × 4 grid</source>
        <translation>Abtastungen auf jedem zweiten Feld eines 4 × 4-Rasters</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fine (%1 samples)</source>
        <translation>Fein (%1 Abtastungen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Eight samples a pixel, each in a row and a column of its own: fine edges</source>
        <translation>Acht Abtastungen je Pixel, jede in einer eigenen Zeile und Spalte: feine Kanten</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Grid %1 × %1 (%2 samples)</source>
        <translation>Raster %1 × %1 (%2 Abtastungen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Samples on a regular %1 × %1 grid a pixel: finer and slower as it grows</source>
        <translation>Abtastungen auf einem regelmäßigen %1 × %1-Raster je Pixel: je größer, desto feiner und langsamer</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Printer profile</source>
        <translation>Druckerprofil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ICC profiles (*.icc *.icm);;All files (*)</source>
        <translation>ICC-Profile (*.icc *.icm);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The image would be %1 × %2 pixels: choose a size of at least 1 pixel.</source>
        <translation>Das Bild hätte %1 × %2 Pixel: wählen Sie eine Größe von mindestens 1 Pixel.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The image would be %L1 × %L2 pixels (%L3 megapixels); Marbler renders at most %L4 pixels a side and %L5 megapixels. Choose a smaller size or a lower resolution.</source>
        <translation>Das Bild hätte %L1 × %L2 Pixel (%L3 Megapixel); Marbler rendert höchstens %L4 Pixel je Seite und %L5 Megapixel. Wählen Sie eine kleinere Größe oder eine geringere Auflösung.</translation>
    </message>
    <message>
        <location filename="../app/shared/SourcePermissions.cpp" line="+23"/>
        <source>Read an image outside the design&apos;s folder?</source>
        <translation>Ein Bild außerhalb des Musterordners lesen?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This design reads an image outside its folder: %1. Read it?</source>
        <translation>Dieses Muster liest ein Bild außerhalb seines Ordners: %1. Lesen?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The design %1 names it. A design may read images only from its own folder unless you allow it; the answer holds until Marbler closes.</source>
        <translation>Das Muster %1 nennt es. Ein Muster darf nur Bilder aus seinem eigenen Ordner lesen, außer Sie erlauben es; die Antwort gilt, bis Marbler geschlossen wird.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Allow</source>
        <translation>Erlauben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Don&apos;t allow</source>
        <translation>Nicht erlauben</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>this design reads an image outside its folder (%1), which you chose not to read</source>
        <translation>dieses Muster liest ein Bild außerhalb seines Ordners (%1), das Sie nicht lesen lassen wollten</translation>
    </message>
    <message>
        <location filename="../app/workbench/WorkbenchPicture.cpp" line="+25"/>
        <source>Pictures (%1);;All files (*)</source>
        <translation>Bilder (%1);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../app/workbench/OpenPlacement.cpp" line="+144"/>
        <source>Marble a picture?</source>
        <translation>Ein Bild marmorieren?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is a picture without a Marbler design in it.

Marble it: nine designs whose bath is the picture, as File ▸ Marble a picture makes?</source>
        <translation>%1 ist ein Bild ohne Marbler-Muster darin.

Es marmorieren: neun Muster, deren Bad das Bild ist, wie Datei ▸ Ein Bild marmorieren sie erzeugt?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Marble the picture</source>
        <translation>Bild &amp;marmorieren</translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <location filename="../app/shared/Language.cpp" line="-19"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save All</source>
        <translation>Alle speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open</source>
        <translation>Öffnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Yes</source>
        <translation>&amp;Ja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yes to &amp;All</source>
        <translation>Ja, &amp;alle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;No</source>
        <translation>&amp;Nein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>N&amp;o to All</source>
        <translation>N&amp;ein, keine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Abort</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retry</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ignore</source>
        <translation>Ignorieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Discard</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Help</source>
        <translation>Hilfe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply</source>
        <translation>Anwenden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore Defaults</source>
        <translation>Standardwerte wiederherstellen</translation>
    </message>
</context>
<context>
    <name>Registry</name>
    <message>
        <location filename="registry-words.cpp" line="+26"/>
        <source>Centre</source>
        <translation>Mitte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>design units</source>
        <translation>Mustereinheiten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>centre of the tool</source>
        <translation>Mitte des Werkzeugs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Origin</source>
        <translation>Ursprung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a point on the stroke&apos;s path</source>
        <translation>ein Punkt auf dem Weg des Zugs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ink</source>
        <translation>Farbe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>palette index of the ink</source>
        <translation>Palettennummer der Farbe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis (turned by the right-hand rule)</source>
        <translation>Achse (gedreht nach der Rechte-Hand-Regel)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>degrees</source>
        <translation>Grad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>direction of motion, clockwise from +x</source>
        <translation>Bewegungsrichtung, im Uhrzeigersinn von +x</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>direction of motion</source>
        <translation>Bewegungsrichtung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Normal</source>
        <translation>Normale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>across the plane the tine sweeps</source>
        <translation>quer zur Ebene, die die Zinke überstreicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shift</source>
        <translation>Verschiebung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>largest shift, at the tine</source>
        <translation>größte Verschiebung, an der Zinke</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sharpness</source>
        <translation>Schärfe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sharpness: smaller concentrates the shift near the tine</source>
        <translation>Schärfe: kleiner bündelt die Verschiebung nahe der Zinke</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spacing</source>
        <translation>Abstand</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>distance between tines</source>
        <translation>Abstand der Zinken</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Amplitude</source>
        <translation>Amplitude</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>largest shift of the wave</source>
        <translation>größte Verschiebung der Welle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wavelength</source>
        <translation>Wellenlänge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>length of one period</source>
        <translation>Länge einer Periode</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Phase</source>
        <translation>Phase</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>phase of the wave</source>
        <translation>Phase der Welle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shape</source>
        <translation>Form</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>shape of the wave</source>
        <translation>Form der Welle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Core</source>
        <translation>Kern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>finite centre: 0 winds without end, larger keeps the swirl&apos;s eye clean</source>
        <translation>endliche Mitte: 0 windet ohne Ende, größer hält das Auge des Strudels sauber</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Teeth</source>
        <translation>Zähne</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tooth positions along the normal, from the origin, increasing</source>
        <translation>Zahnpositionen entlang der Normalen, vom Ursprung aus, aufsteigend</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>largest shift, midway between two teeth; its sign is the direction</source>
        <translation>größte Verschiebung, mittig zwischen zwei Zähnen; ihr Vorzeichen ist die Richtung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Profile</source>
        <translation>Profil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tooth profile |sin|^p: small is blunt, large is pointed</source>
        <translation>Zahnprofil |sin|^p: klein ist stumpf, groß ist spitz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Field</source>
        <translation>Feld</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the velocity field: a lattice of cells or one cavity</source>
        <translation>das Geschwindigkeitsfeld: ein Gitter aus Zellen oder ein Hohlraum</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Size</source>
        <translation>Größe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>size of a cell (cells) or of the box (cavity)</source>
        <translation>Größe einer Zelle (Zellen) oder des Kastens (Hohlraum)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>design units per time unit</source>
        <translation>Mustereinheiten je Zeiteinheit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed of the flow; its sign is the sense of turning</source>
        <translation>Geschwindigkeit der Strömung; ihr Vorzeichen ist der Drehsinn</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>time units</source>
        <translation>Zeiteinheiten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>how long the flow runs</source>
        <translation>wie lange die Strömung läuft</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>implicit midpoint steps (at least 32 |speed| time max(size) / min(size)^2)</source>
        <translation>implizite Mittelpunktschritte (mindestens 32 |Geschwindigkeit| Zeit max(Größe) / min(Größe)^2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Path</source>
        <translation>Pfad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the polyline the stylus is drawn along</source>
        <translation>der Polygonzug, entlang dem der Stift gezogen wird</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pull</source>
        <translation>Zug</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>strength of the pull along the path, about the shift on the track</source>
        <translation>Stärke des Zugs entlang des Pfads, etwa die Verschiebung auf der Spur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>how far to the side the pull reaches</source>
        <translation>wie weit der Zug zur Seite reicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reach</source>
        <translation>Reichweite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>how far ahead of and behind the stylus the bath moves</source>
        <translation>wie weit vor und hinter dem Stift sich das Bad bewegt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tines</source>
        <translation>Zinken</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 a stylus, more a rake</source>
        <translation>1 ein Stift, mehr ein Rechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>distance between the rake&apos;s tines (required with more than one)</source>
        <translation>Abstand der Zinken des Rechens (nötig bei mehr als einer)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pressure</source>
        <translation>Druck</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a pen&apos;s pressure, one value in [0, 1] per path point</source>
        <translation>der Druck eines Grafikstifts, ein Wert in [0, 1] je Pfadpunkt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>integration steps (at least 4 L / reach and the contraction rule)</source>
        <translation>Integrationsschritte (mindestens 4 L / Reichweite und die Kontraktionsregel)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drop</source>
        <translation>Tropfen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>spray</source>
        <translation>Sprühen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cylinder</source>
        <translation>Zylinder</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>line</source>
        <translation>Linie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>comb</source>
        <translation>Kamm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wave</source>
        <translation>Welle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>circle</source>
        <translation>Kreis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>vortex</source>
        <translation>Wirbel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stretch</source>
        <translation>Dehnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flow</source>
        <translation>Strömung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stylus</source>
        <translation>Stift</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drops</source>
        <translation>Tropfen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sprays</source>
        <translation>Sprühungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cylinders</source>
        <translation>Zylinder</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lines</source>
        <translation>Linien</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>combs</source>
        <translation>Kämme</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>waves</source>
        <translation>Wellen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>circles</source>
        <translation>Kreise</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>spheres</source>
        <translation>Kugeln</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>vortices</source>
        <translation>Wirbel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stretches</source>
        <translation>Dehnungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flows</source>
        <translation>Strömungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stylus strokes</source>
        <translation>Stiftzüge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stone</source>
        <translation>Steinmarmor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>battal: drops only, big first, later colours smaller</source>
        <translation>Battal: nur Tropfen, zuerst große, spätere Farben kleiner</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gel git</source>
        <translation>Gel-git (Kommen und Gehen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stone combed one way and back (come and go)</source>
        <translation>Steinmarmor in eine Richtung und zurück gekämmt (Kommen und Gehen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Chevron</source>
        <translation>Fischgrat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gel-git, then one wide comb across: rows of chevrons</source>
        <translation>Gel-git, dann ein weiter Kamm quer: Reihen von Fischgräten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nonpareil</source>
        <translation>Nonpareil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gel-git, then a fine comb across: rows of small points</source>
        <translation>Gel-git, dann ein feiner Kamm quer: Reihen kleiner Spitzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bouquet</source>
        <translation>Bukett</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nonpareil, then a rake in a serpentine: rows of fans</source>
        <translation>Nonpareil, dann ein Rechen in Schlangenlinien: Reihen von Fächern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Peacock</source>
        <translation>Pfau</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bouquet, then the rake back between: rows of eyes</source>
        <translation>Bukett, dann der Rechen dazwischen zurück: Reihen von Augen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>French curl</source>
        <translation>Französische Locke</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>curls on a grid over a nonpareil or gel-git</source>
        <translation>Locken auf einem Gitter über Nonpareil oder Gel-git</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spanish wave</source>
        <translation>Spanische Welle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stone rocked into bands (a stretch pass)</source>
        <translation>Steinmarmor in Bänder gewiegt (ein Dehnungsdurchgang)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Birds nest</source>
        <translation>Vogelnest</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bülbül yuvası: a small curl in each drop</source>
        <translation>Bülbül yuvası: eine kleine Locke in jedem Tropfen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shawl</source>
        <translation>Schal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>şal: gel-git, then a wide comb in long waves</source>
        <translation>Şal: Gel-git, dann ein weiter Kamm in langen Wellen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tiger eye</source>
        <translation>Tigerauge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stone sprinkled with small bright spots</source>
        <translation>Steinmarmor mit kleinen hellen Tupfen besprenkelt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zebra</source>
        <translation>Zebra</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bull&apos;s-eyes of two inks combed into stripes</source>
        <translation>Ringscheiben aus zwei Farben, zu Streifen gekämmt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>First paper</source>
        <translation>Erstes Papier</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stone, combs both ways across and down, a wave (Lu et al. 2012)</source>
        <translation>Steinmarmor, Kämme in beide Richtungen quer und längs, eine Welle (Lu et al. 2012)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hearts</source>
        <translation>Herzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ebru hearts: rows of ringed drops, a stylus drawn through each row</source>
        <translation>Ebru-Herzen: Reihen geringelter Tropfen, ein Stift durch jede Reihe gezogen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tulip</source>
        <translation>Tulpe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lale: ringed drops pulled into cups by a short stroke each</source>
        <translation>Lale: geringelte Tropfen, jeder mit einem kurzen Zug zu einem Kelch gezogen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Carnation</source>
        <translation>Nelke</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>karanfil: ringed drops fringed by short strokes round the edge</source>
        <translation>Karanfil: geringelte Tropfen, am Rand mit kurzen Zügen gefranst</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Curls</source>
        <translation>Locken</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>free-hand French curl: a stylus drawn in spirals through a gel-git</source>
        <translation>Freihändige französische Locke: ein Stift in Spiralen durch ein Gel-git gezogen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Veined</source>
        <translation>Geädert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>solid: spheres of ink drawn into veins by combs</source>
        <translation>räumlich: Farbkugeln, von Kämmen zu Adern gezogen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Agate</source>
        <translation>Achat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>solid: columns of banded ink, waved</source>
        <translation>räumlich: Säulen gebänderter Farbe, gewellt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Granite</source>
        <translation>Granit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>solid: speckles over close-packed grains</source>
        <translation>räumlich: Sprenkel über dicht gepackten Körnern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>styluses</source>
        <translation>Stiftzüge</translation>
    </message>
</context>
<context>
    <name>marbler::ui</name>
    <message>
        <location filename="../app/editor/BathSizes.cpp" line="+24"/>
        <source>&amp;Square</source>
        <translation>&amp;Quadratisch</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>A4 &amp;portrait</source>
        <translation>A4 &amp;hoch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A4 &amp;landscape</source>
        <translation>A4 &amp;quer</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;16:9 (wide)</source>
        <translation>&amp;16:9 (breit)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;9:16 (tall)</source>
        <translation>&amp;9:16 (hoch)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Flat bath of si&amp;ze</source>
        <translation>Flaches Bad der &amp;Größe</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Solid bl&amp;ock of size</source>
        <translation>Räumlicher Bl&amp;ock der Größe</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>A blank bath %1 × %2 design units</source>
        <translation>Ein leeres Bad von %1 × %2 Mustereinheiten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A blank block %1 × %2 × %3 design units</source>
        <translation>Ein leerer Block von %1 × %2 × %3 Mustereinheiten</translation>
    </message>
    <message>
        <location filename="../app/shared/Help.cpp" line="+62"/>
        <source>View</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show or hide %1</source>
        <translation>%1 ein- oder ausblenden</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Keys</source>
        <translation>Tasten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Does</source>
        <translation>Wirkung</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Menu</source>
        <translation>Menü</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&lt;h2&gt;Marbler %1&lt;/h2&gt;&lt;p&gt;A workbench for breeding marbled designs, after &lt;i&gt;mathematical marbling&lt;/i&gt; (Lu, Jaffer, Jin, Zhao, Mao, IEEE CG&amp;amp;A 2012).&lt;/p&gt;</source>
        <translation>&lt;h2&gt;Marbler %1&lt;/h2&gt;&lt;p&gt;Eine Werkbank zum Züchten marmorierter Muster, nach &lt;i&gt;mathematischem Marmorieren&lt;/i&gt; (Lu, Jaffer, Jin, Zhao, Mao, IEEE CG&amp;amp;A 2012).&lt;/p&gt;</translation>
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
        <translation>nicht geladen: es wird beim ersten Export nach EXR, JPEG oder einem anderen Format außer PNG und TIFF geladen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Renderer</source>
        <translation>Renderer</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>being chosen…</source>
        <translation>wird gewählt…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;p&gt;Choose the renderer in View ▸ Renderer; the environment variable %1=auto|gpu|cpu overrides it.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Wählen Sie den Renderer unter Ansicht ▸ Renderer; die Umgebungsvariable %1=auto|gpu|cpu hat Vorrang.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/shared/Lineage.cpp" line="-21"/>
        <source>Alter</source>
        <translation>Abwandeln</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Recombine</source>
        <translation>Rekombinieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Swap</source>
        <translation>Tauschen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Change initial state</source>
        <translation>Anfangszustand ändern</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Wildcard</source>
        <translation>Joker</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Colourway</source>
        <translation>Farbvariante</translation>
    </message>
    <message>
        <location filename="../app/shared/MeshChooser.cpp" line="+7"/>
        <source>%1: no such mesh file</source>
        <translation>%1: keine solche Mesh-Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: not a mesh file</source>
        <translation>%1: keine Mesh-Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: the mesh file cannot be read (permission denied)</source>
        <translation>%1: die Mesh-Datei kann nicht gelesen werden (keine Berechtigung)</translation>
    </message>
    <message>
        <location filename="../app/workbench/SessionStore.cpp" line="+133"/>
        <source>Solid session, %1</source>
        <translation>Räumliche Sitzung, %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Flat session, %1</source>
        <translation>Flache Sitzung, %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>generation %1</source>
        <translation>Generation %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>solid</source>
        <translation>räumlich</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flat</source>
        <translation>flach</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>changed %1</source>
        <translation>geändert %1</translation>
    </message>
    <message>
        <location filename="../app/shared/Language.cpp" line="+104"/>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;System language</source>
        <translation>&amp;Systemsprache</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The window&apos;s language from the next start of Marbler</source>
        <translation>Die Sprache des Fensters ab dem nächsten Start von Marbler</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The language changes when Marbler starts again</source>
        <translation>Die Sprache wechselt beim nächsten Start von Marbler</translation>
    </message>
</context>
<context>
    <name>marbler::ui::AnimationExportDialog</name>
    <message>
        <location filename="../app/editor/AnimationExport.cpp" line="+59"/>
        <location line="+105"/>
        <source>Export animation</source>
        <translation>Animation exportieren</translation>
    </message>
    <message>
        <location line="-103"/>
        <source>PNG frames (a folder)</source>
        <translation>PNG-Einzelbilder (ein Ordner)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GIF</source>
        <translation>GIF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>WebP (animated)</source>
        <translation>WebP (animiert)</translation>
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
        <translation>Was geschrieben wird: ein Ordner mit PNG-Einzelbildern (jedes trägt das Muster, das es zeigt), ein animiertes Bild oder ein Video</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The file to write, or for PNG frames a new or empty folder</source>
        <translation>Die zu schreibende Datei, bei PNG-Einzelbildern ein neuer oder leerer Ordner</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Browse…</source>
        <translation>&amp;Durchsuchen…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose where to write the animation</source>
        <translation>Wählen Sie, wohin die Animation geschrieben wird</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Width of each frame in pixels</source>
        <translation>Breite jedes Einzelbilds in Pixeln</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Height of each frame in pixels</source>
        <translation>Höhe jedes Einzelbilds in Pixeln</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Number of frames: the first shows the bare bath, the last the whole design</source>
        <translation>Anzahl der Einzelbilder: das erste zeigt das leere Bad, das letzte das ganze Muster</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Frames a second of a video or animated image</source>
        <translation>Bilder pro Sekunde eines Videos oder animierten Bildes</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>How long the animation plays: the frames at the frame rate (changing it sets the number of frames)</source>
        <translation>Wie lange die Animation läuft: die Einzelbilder bei der Bildrate (eine Änderung legt die Anzahl der Einzelbilder fest)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>&amp;Format:</source>
        <translation>&amp;Format:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Save to:</source>
        <translation>&amp;Speichern unter:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Si&amp;ze:</source>
        <translation>Grö&amp;ße:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>F&amp;rames:</source>
        <translation>&amp;Einzelbilder:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frames a &amp;second:</source>
        <translation>Bilder pro &amp;Sekunde:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Duration:</source>
        <translation>&amp;Dauer:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Folder for the PNG frames</source>
        <translation>Ordner für die PNG-Einzelbilder</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 files (*.%2)</source>
        <translation>%1-Dateien (*.%2)</translation>
    </message>
</context>
<context>
    <name>marbler::ui::AnimationExportJob</name>
    <message>
        <location line="+59"/>
        <source>Writing the making of the design…</source>
        <translation>Die Entstehung des Musters wird geschrieben…</translation>
    </message>
</context>
<context>
    <name>marbler::ui::ColourwaysController</name>
    <message>
        <location filename="../app/workbench/ColourwaysController.cpp" line="+56"/>
        <source>&amp;Colourways</source>
        <translation>&amp;Farbvarianten</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Breed only palettes, as textile designers make colourways: with one design picked, fills the grid with it and eight colourways of it (Ctrl+5)</source>
        <translation>Nur Paletten züchten, wie Textildesigner Farbvarianten anlegen: ist ein Muster gewählt, füllt es das Raster mit ihm und acht Farbvarianten davon (Strg+5)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Export colourway sheet…</source>
        <translation>Farbvarianten-&amp;Bogen exportieren…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The grid&apos;s designs side by side in one PNG or TIFF image, each named</source>
        <translation>Die Muster des Rasters nebeneinander in einem PNG- oder TIFF-Bild, jedes mit seinem Namen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Colourway sheet with ink c&amp;hips</source>
        <translation>Farbvarianten-Bogen mit Farbfel&amp;dern</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Put each design&apos;s inks, with their hex values, under its name on the sheet</source>
        <translation>Die Farben jedes Musters mit ihren Hex-Werten auf dem Bogen unter seinen Namen setzen</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Colourways off: the operators breed whole designs again</source>
        <translation>Farbvarianten aus: die Operatoren züchten wieder ganze Muster</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Colourways on: Alter varies the picked design&apos;s palette, Recombine mixes the parents&apos; palettes; the structure stays</source>
        <translation>Farbvarianten an: Abwandeln variiert die Palette des gewählten Musters, Rekombinieren mischt die Paletten der Eltern; die Struktur bleibt</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Colourways of %1</source>
        <translation>Farbvarianten von %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+51"/>
        <source>Cannot make colourways</source>
        <translation>Farbvarianten können nicht erzeugt werden</translation>
    </message>
    <message>
        <location line="-48"/>
        <source>Generation %1: %2 and eight colourways of it</source>
        <translation>Generation %1: %2 und acht Farbvarianten davon</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Colourways of the parent: its palette varied, its structure kept; the slider sets how much</source>
        <translation>Farbvarianten des Elternmusters: Palette variiert, Struktur erhalten; der Schieberegler bestimmt, wie stark</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Colourways whose palettes mix the parents&apos; inks; the structure of each is kept</source>
        <translation>Farbvarianten, deren Paletten die Farben der Eltern mischen; die Struktur jedes Musters bleibt erhalten</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Off in Colourways mode: %1 changes the structure, which colourways keep. Turn Breed ▸ Colourways off to use it</source>
        <translation>Im Farbvarianten-Modus aus: %1 ändert die Struktur, die Farbvarianten erhalten. Schalten Sie Züchten ▸ Farbvarianten aus, um es zu nutzen</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 is off in Colourways mode: colourways keep the structure</source>
        <translation>%1 ist im Farbvarianten-Modus aus: Farbvarianten erhalten die Struktur</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Colourways: generation %1</source>
        <translation>Farbvarianten: Generation %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>A colourway sheet is being written already</source>
        <translation>Ein Farbvarianten-Bogen wird bereits geschrieben</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>No designs to put on a sheet yet</source>
        <translation>Noch keine Muster für einen Bogen</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+45"/>
        <source>Export colourway sheet</source>
        <translation>Farbvarianten-Bogen exportieren</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>PNG image (*.png);;TIFF image (*.tif *.tiff)</source>
        <translation>PNG-Bild (*.png);;TIFF-Bild (*.tif *.tiff)</translation>
    </message>
    <message>
        <location line="+14"/>
        <location line="+24"/>
        <source>Cannot export the colourway sheet</source>
        <translation>Der Farbvarianten-Bogen kann nicht exportiert werden</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>Rendering the colourway sheet…</source>
        <translation>Der Farbvarianten-Bogen wird gerendert…</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Colourway sheet cancelled</source>
        <translation>Farbvarianten-Bogen abgebrochen</translation>
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
        <translation>Muster %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Click to choose as a parent, double-click to open large, F2 to rename, right-click for locks and favourites. Drop a genome file, or a PNG or TIFF Marbler exported, here to load it.</source>
        <translation>Klicken, um es als Elternteil zu wählen, Doppelklick öffnet es groß, F2 benennt es um, Rechtsklick für Sperren und Favoriten. Legen Sie hier eine Genomdatei oder ein von Marbler exportiertes PNG oder TIFF ab, um es zu laden.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Changed: %1

%2</source>
        <translation>Geändert: %1

%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Note: %1

%2</source>
        <translation>Notiz: %1

%2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>selected as a parent</source>
        <translation>als Elternteil gewählt</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>Empty
open or drop a design here</source>
        <translation>Leer
hier ein Muster öffnen oder ablegen</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>rendering…</source>
        <translation>wird gerendert…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot render: %1</source>
        <translation>Rendern nicht möglich: %1</translation>
    </message>
</context>
<context>
    <name>marbler::ui::DesignDialog</name>
    <message>
        <location filename="../app/shared/DesignDialog.cpp" line="-376"/>
        <location line="+352"/>
        <source>Design %1</source>
        <translation>Muster %1</translation>
    </message>
    <message>
        <location line="-333"/>
        <source>Zoom out (-, wheel)</source>
        <translation>Verkleinern (-, Mausrad)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom in (+, wheel)</source>
        <translation>Vergrößern (+, Mausrad)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fit</source>
        <translation>Einpassen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frame the whole object (0)</source>
        <translation>Das ganze Objekt einrahmen (0)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Show the whole design (0)</source>
        <translation>Das ganze Muster zeigen (0)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1:1</source>
        <translation>1:1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One design unit to a screen pixel, the scale of an export as many pixels wide as the design is wide (1)</source>
        <translation>Eine Mustereinheit je Bildschirmpixel, der Maßstab eines Exports, der so viele Pixel breit ist wie das Muster Einheiten (1)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Magnification of the framed object</source>
        <translation>Vergrößerung des eingerahmten Objekts</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Screen pixels per design unit (100 %: one to one)</source>
        <translation>Bildschirmpixel je Mustereinheit (100 %: eins zu eins)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Repeat swatch</source>
        <translation>Rapportmuster</translation>
    </message>
    <message>
        <location line="-68"/>
        <source>Flat designs only: a solid has no repeat tile</source>
        <translation>Nur flache Muster: ein räumliches hat keine Rapportkachel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show the whole design tiled as its mirror repeat, 2 × 2, to judge the repeat (R)</source>
        <translation>Das ganze Muster als Spiegelrapport 2 × 2 gekachelt zeigen, um den Rapport zu beurteilen (R)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Show the design repeated 2 × 2 as its straight repeat, to judge the repeat (R)</source>
        <translation>Das Muster als geraden Rapport 2 × 2 wiederholt zeigen, um den Rapport zu beurteilen (R)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show the design repeated 2 × 2 as its half-drop repeat, to judge the repeat (R)</source>
        <translation>Das Muster als Halbversatz-Rapport 2 × 2 wiederholt zeigen, um den Rapport zu beurteilen (R)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show the design repeated 2 × 2 as its brick repeat, to judge the repeat (R)</source>
        <translation>Das Muster als Ziegel-Rapport 2 × 2 wiederholt zeigen, um den Rapport zu beurteilen (R)</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>Section</source>
        <translation>Schnitt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show a cross-section of the solid instead of the object; move it and turn it to any angle below (S)</source>
        <translation>Statt des Objekts einen Querschnitt des räumlichen Musters zeigen; unten lässt er sich verschieben und in jeden Winkel drehen (S)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&amp;Save genome…</source>
        <translation>Genom &amp;speichern…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the design as a genome file (Ctrl+S)</source>
        <translation>Das Muster als Genomdatei speichern (Strg+S)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export image…</source>
        <translation>Bild &amp;exportieren…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Render the design to PNG, TIFF, EXR or JPEG at any size, or a flat one to SVG (Ctrl+E)</source>
        <translation>Das Muster in beliebiger Größe als PNG, TIFF, EXR oder JPEG rendern, ein flaches auch als SVG (Strg+E)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Copy genome</source>
        <translation>Genom &amp;kopieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Put the design&apos;s genome on the clipboard as text, to paste into the workbench or anywhere else (%1)</source>
        <translation>Das Genom des Musters als Text in die Zwischenablage legen, zum Einfügen in die Werkbank oder anderswo (%1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Open in e&amp;ditor</source>
        <translation>Im E&amp;ditor öffnen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Edit this design step by step in the editor (Ctrl+Shift+D)</source>
        <translation>Dieses Muster im Editor Schritt für Schritt bearbeiten (Strg+Umschalt+D)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Rename…</source>
        <translation>Umbenennen…</translation>
    </message>
    <message>
        <location line="+156"/>
        <source>Export separations into a folder</source>
        <translation>Farbauszüge in einen Ordner exportieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> separations</source>
        <translation> Farbauszüge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Folders (*)</source>
        <translation>Ordner (*)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Export image</source>
        <translation>Bild exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SVG drawings (*.svg)</source>
        <translation>SVG-Zeichnungen (*.svg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Images (*%1);;All images (*.png *.tif *.tiff *.exr *.jpg *.jpeg)</source>
        <translation>Bilder (*%1);;Alle Bilder (*.png *.tif *.tiff *.exr *.jpg *.jpeg)</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>the design</source>
        <translation>das Muster</translation>
    </message>
</context>
<context>
    <name>marbler::ui::DesignExport</name>
    <message>
        <location filename="../app/shared/DesignExport.cpp" line="+24"/>
        <source>Export cancelled: %1 was not written</source>
        <translation>Export abgebrochen: %1 wurde nicht geschrieben</translation>
    </message>
    <message>
        <location line="+21"/>
        <location line="+69"/>
        <location line="+21"/>
        <location line="+38"/>
        <source>Cannot export the image</source>
        <translation>Das Bild kann nicht exportiert werden</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>Exporting %1…</source>
        <translation>%1 wird exportiert…</translation>
    </message>
</context>
<context>
    <name>marbler::ui::DesignView</name>
    <message>
        <location filename="../app/shared/DesignView.cpp" line="+49"/>
        <location line="+218"/>
        <source>Drag to turn the object; wheel, + and - zoom</source>
        <translation>Ziehen dreht das Objekt; Mausrad, + und - zoomen</translation>
    </message>
    <message>
        <location line="-217"/>
        <source>Wheel, + and - zoom about the pointer; drag to pan</source>
        <translation>Mausrad, + und - zoomen um den Mauszeiger; Ziehen verschiebt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>rendering…</source>
        <translation>wird gerendert…</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Cannot render: %1</source>
        <translation>Rendern nicht möglich: %1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>%L1 %</source>
        <translation>%L1 %</translation>
    </message>
    <message>
        <location line="+165"/>
        <source>The cross-section: the section controls below move and turn it</source>
        <translation>Der Querschnitt: die Schnitt-Regler unten verschieben und drehen ihn</translation>
    </message>
</context>
<context>
    <name>marbler::ui::EditorCanvas</name>
    <message>
        <location filename="../app/editor/EditorCanvas.cpp" line="+85"/>
        <source>Drag with the current tool (Esc drops the drag); middle or right drag (or Space and drag) pans, the wheel zooms, 0 fits, 1 shows one to one</source>
        <translation>Mit dem aktuellen Werkzeug ziehen (Esc bricht ab); Ziehen mit mittlerer oder rechter Taste (oder Leertaste und Ziehen) verschiebt, das Mausrad zoomt, 0 passt ein, 1 zeigt eins zu eins</translation>
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
        <translation>Nicht ausgeführt: das Bad dieses Musters läuft um (es ist eine Rapportkachel), und %1. Bearbeiten ▸ Umlaufendes Bad schaltet das Umlaufen aus und erlaubt jedes Werkzeug.</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>Add %1</source>
        <translation>%1 hinzufügen</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Delete %1</source>
        <translation>%1 löschen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Duplicate %1</source>
        <translation>%1 duplizieren</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Move %1 to %2</source>
        <translation>%1 nach %2 verschieben</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Mute %1</source>
        <translation>%1 stummschalten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unmute %1</source>
        <translation>%1 wieder einschalten</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Mute steps %1–%2</source>
        <translation>Schritte %1–%2 stummschalten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unmute steps %1–%2</source>
        <translation>Schritte %1–%2 wieder einschalten</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Ink %1: %2 → %3</source>
        <translation>Farbe %1: %2 → %3</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Add ink %1: %2</source>
        <translation>Farbe %1 hinzufügen: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Background: %1 → %2</source>
        <translation>Hintergrund: %1 → %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Bleed: %1 → %2</source>
        <translation>Verlaufen: %1 → %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Wrap the bath</source>
        <translation>Umlaufendes Bad einschalten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unwrap the bath</source>
        <translation>Umlaufendes Bad ausschalten</translation>
    </message>
    <message>
        <location line="+211"/>
        <source>Delete ink %1: %2</source>
        <translation>Farbe %1 löschen: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, its steps in ink %1</source>
        <translation>, seine Schritte in Farbe %1</translation>
    </message>
</context>
<context>
    <name>marbler::ui::EditorExports</name>
    <message>
        <location filename="../app/editor/EditorExports.cpp" line="+48"/>
        <location line="+29"/>
        <source>An animation is being written already</source>
        <translation>Eine Animation wird bereits geschrieben</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>Wrote %1</source>
        <translation>%1 geschrieben</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot write the animation</source>
        <translation>Die Animation kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Animation cancelled; nothing was written</source>
        <translation>Animation abgebrochen; nichts wurde geschrieben</translation>
    </message>
</context>
<context>
    <name>marbler::ui::EditorFiles</name>
    <message>
        <location filename="../app/editor/EditorFiles.cpp" line="+45"/>
        <source>Designs (*.marble.json *.json *.png *.tif *.tiff);;All files (*)</source>
        <translation>Muster (*.marble.json *.json *.png *.tif *.tiff);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+44"/>
        <source>Untitled design</source>
        <translation>Unbenanntes Muster</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Save a design opened from an image</source>
        <translation>Ein aus einem Bild geöffnetes Muster speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>“%1” is an image. Save the design as a design file, or write the image again with the design inside?</source>
        <translation>„%1“ ist ein Bild. Das Muster als Musterdatei speichern oder das Bild mit dem Muster darin neu schreiben?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save as design file…</source>
        <translation>Als Musterdatei speichern…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Update the image</source>
        <translation>Das Bild aktualisieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Render the design into %1 at its size; the picture there is replaced</source>
        <translation>Das Muster in seiner Größe in %1 rendern; das Bild dort wird ersetzt</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Save design</source>
        <translation>Muster speichern</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Marbler designs (*.marble.json)</source>
        <translation>Marbler-Muster (*.marble.json)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Name “%1”</source>
        <translation>Namen „%1“ vergeben</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The file was changed</source>
        <translation>Die Datei wurde geändert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>“%1” was changed by another program or window since it was opened here. Overwrite those changes, reload the file (your changes stay in Undo), or save under another name?</source>
        <translation>„%1“ wurde seit dem Öffnen hier von einem anderen Programm oder Fenster geändert. Diese Änderungen überschreiben, die Datei neu laden (Ihre Änderungen bleiben im Rückgängig-Verlauf) oder unter einem anderen Namen speichern?</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Overwrite</source>
        <translation>Überschreiben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reload</source>
        <translation>Neu laden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save as…</source>
        <translation>Speichern unter…</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Cannot save the design</source>
        <translation>Das Muster kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Reload %1</source>
        <translation>%1 neu laden</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot reload the design</source>
        <translation>Das Muster kann nicht neu geladen werden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Reloaded %1; Undo brings your changes back</source>
        <translation>%1 neu geladen; Rückgängig holt Ihre Änderungen zurück</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The image is being written already</source>
        <translation>Das Bild wird bereits geschrieben</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Writing %1…</source>
        <translation>%1 wird geschrieben…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Wrote %1 with the design inside</source>
        <translation>%1 mit dem Muster darin geschrieben</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot write the image</source>
        <translation>Das Bild kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cancelled; the image is as it was</source>
        <translation>Abgebrochen; das Bild ist unverändert</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Replace the file?</source>
        <translation>Die Datei ersetzen?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>“%1” exists already. Replace it?</source>
        <translation>„%1“ existiert bereits. Ersetzen?</translation>
    </message>
    <message>
        <location line="+27"/>
        <location line="+16"/>
        <source>Cannot open the design</source>
        <translation>Das Muster kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>No recent designs</source>
        <translation>Keine zuletzt geöffneten Muster</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open a design</source>
        <translation>Ein Muster öffnen</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>A picture for the bath</source>
        <translation>Ein Bild für das Bad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Images (*.png *.jpg *.jpeg *.tif *.tiff *.webp *.bmp)</source>
        <translation>Bilder (*.png *.jpg *.jpeg *.tif *.tiff *.webp *.bmp)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>“%1” has changes that are not saved. Save them?</source>
        <translation>„%1“ hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
</context>
<context>
    <name>marbler::ui::EditorWindow</name>
    <message>
        <location filename="../app/editor/EditorWindow.cpp" line="+229"/>
        <source>Steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Inks</source>
        <translation>Farben</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New design</source>
        <translation>&amp;Neues Muster</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Blank &amp;flat bath</source>
        <translation>Leeres &amp;flaches Bad</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Blank &amp;solid block</source>
        <translation>Leerer &amp;räumlicher Block</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Random design</source>
        <translation>&amp;Zufälliges Muster</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From a &amp;picture…</source>
        <translation>Aus einem &amp;Bild…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A flat design whose bath is a picture (its source)</source>
        <translation>Ein flaches Muster, dessen Bad ein Bild ist (seine Quelle)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open &amp;recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save &amp;as…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+Shift+S</source>
        <translation>Ctrl+Shift+S</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export image…</source>
        <translation>Bild &amp;exportieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export &amp;animation…</source>
        <translation>&amp;Animation exportieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Baked onto %1</source>
        <translation>Auf das Objekt gebacken: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Send to &amp;grid</source>
        <translation>An das &amp;Raster senden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sent to the breeding grid</source>
        <translation>An das Zuchtraster gesendet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+G</source>
        <translation>Ctrl+G</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Put this design into the breeding grid as a new design to breed from</source>
        <translation>Dieses Muster als neues Muster zum Weiterzüchten in das Zuchtraster legen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Recover &amp;unsaved designs…</source>
        <translation>&amp;Ungespeicherte Muster wiederherstellen…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Designs that editors left unsaved when Marbler stopped, kept until you discard them</source>
        <translation>Muster, die Editoren beim Beenden von Marbler ungespeichert ließen, aufbewahrt, bis Sie sie verwerfen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Close</source>
        <translation>S&amp;chließen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
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
        <translation>&amp;Umbenennen…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Names the design and gives it a note (one undo step)</source>
        <translation>Benennt das Muster und gibt ihm eine Notiz (ein Rückgängig-Schritt)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Bath &amp;wraps (straight repeat)</source>
        <translation>Umlaufendes &amp;Bad (gerader Rapport)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tools</source>
        <translation>Werkzeuge</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Fit</source>
        <translation>&amp;Einpassen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>0</source>
        <translation>0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom &amp;in</source>
        <translation>Ver&amp;größern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom &amp;out</source>
        <translation>Ver&amp;kleinern</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Compare two states</source>
        <translation>Zwei Zustände &amp;vergleichen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ctrl+K</source>
        <translation>Ctrl+K</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Play the making</source>
        <translation>Entstehung &amp;abspielen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Show on &amp;object</source>
        <translation>Auf &amp;Objekt zeigen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Ctrl+Shift+O</source>
        <translation>Ctrl+Shift+O</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show the design on an object beside the canvas, updated after each edit</source>
        <translation>Das Muster neben der Zeichenfläche auf einem Objekt zeigen, nach jeder Bearbeitung aktualisiert</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Repeat preview</source>
        <translation>&amp;Rapportvorschau</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;Off</source>
        <translation>&amp;Aus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Plain repeat (3 × 3)</source>
        <translation>&amp;Einfacher Rapport (3 × 3)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+R</source>
        <translation>Ctrl+Shift+R</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Mirror repeat (3 × 3)</source>
        <translation>&amp;Spiegelrapport (3 × 3)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+M</source>
        <translation>Ctrl+Shift+M</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Show the design tiled 3 × 3, plainly or as the mirror repeat tile, to judge its seams</source>
        <translation>Das Muster 3 × 3 gekachelt zeigen, einfach oder als Spiegelrapport, um seine Nahtstellen zu beurteilen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Editor &amp;guide</source>
        <translation>Editor-&amp;Anleitung</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>How the editor works, and every keyboard shortcut</source>
        <translation>Wie der Editor funktioniert, und alle Tastenkürzel</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Marbler editor guide</source>
        <translation>Anleitung zum Marbler-Editor</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&lt;h2&gt;The editor&lt;/h2&gt;&lt;p&gt;A design is a list of steps: inks dropped on the bath, then strokes that move them. Pick a tool, then click or drag on the canvas; a new step goes after the selected step (or at the timeline&apos;s point) and the canvas shows the design just after it. The stylus draws free-hand: its path follows the drag (a pen&apos;s pressure too), the panel sets its pull, reach and rake, and its path&apos;s points are its handles.&lt;/p&gt;&lt;p&gt;Select a step to change it in the form or with its handles, however far back; mute, duplicate, move or delete it from the list. Undo and redo work from anywhere; edits you undo and then leave by making another stay under History ▸ Other branches, one click away.&lt;/p&gt;&lt;p&gt;The timeline scrubs through the making of the design, plays it and compares two states. Inks holds the palette and the bath&apos;s colour.&lt;/p&gt;&lt;h3&gt;Keys&lt;/h3&gt;</source>
        <translation>&lt;h2&gt;Der Editor&lt;/h2&gt;&lt;p&gt;Ein Muster ist eine Liste von Schritten: Farben, aufs Bad getropft, dann Züge, die sie bewegen. Wählen Sie ein Werkzeug, dann klicken oder ziehen Sie auf der Zeichenfläche; ein neuer Schritt kommt nach dem gewählten Schritt (oder an die Stelle der Zeitleiste), und die Zeichenfläche zeigt das Muster direkt danach. Der Stift zeichnet freihändig: sein Pfad folgt dem Ziehen (auch dem Druck eines Grafikstifts), das Bedienfeld stellt Zug, Reichweite und Rechen ein, und die Punkte seines Pfads sind seine Griffe.&lt;/p&gt;&lt;p&gt;Wählen Sie einen Schritt, um ihn im Formular oder mit seinen Griffen zu ändern, wie weit zurück er auch liegt; in der Liste schalten Sie ihn stumm, duplizieren, verschieben oder löschen ihn. Rückgängig und Wiederholen wirken von überall; Bearbeitungen, die Sie rückgängig machen und dann durch eine neue verlassen, bleiben unter Verlauf ▸ Andere Zweige, einen Klick entfernt.&lt;/p&gt;&lt;p&gt;Die Zeitleiste fährt durch die Entstehung des Musters, spielt sie ab und vergleicht zwei Zustände. Farben enthält die Palette und die Farbe des Bades.&lt;/p&gt;&lt;h3&gt;Tasten&lt;/h3&gt;</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Added as step %1 of %2; the timeline shows the design up to it (End shows all)</source>
        <translation>Als Schritt %1 von %2 hinzugefügt; die Zeitleiste zeigt das Muster bis dahin (Ende zeigt alles)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Ink %1 picked</source>
        <translation>Farbe %1 gewählt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The bare bath</source>
        <translation>Das leere Bad</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>A design holds at most %1 inks</source>
        <translation>Ein Muster hat höchstens %1 Farben</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Ink %1 is laid by steps and there is no other ink for them</source>
        <translation>Farbe %1 wird von Schritten gelegt, und es gibt keine andere Farbe für sie</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Palette: %1</source>
        <translation>Palette: %1</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>The bath wraps: the design is a repeat tile, and takes only spray and stretch along an axis. Turn it off to use every tool.</source>
        <translation>Das Bad läuft um: das Muster ist eine Rapportkachel und nimmt nur Sprühen und Dehnen entlang einer Achse an. Schalten Sie es aus, um jedes Werkzeug zu nutzen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Make the bath wrap: the design becomes a straight-repeat tile</source>
        <translation>Das Bad umlaufen lassen: das Muster wird eine Kachel mit geradem Rapport</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This design cannot wrap: %1</source>
        <translation>Das Bad dieses Musters kann nicht umlaufen: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 (not in a bath that wraps: turn off Edit ▸ Bath wraps to use it)</source>
        <translation>%1 (nicht in einem umlaufenden Bad: schalten Sie Bearbeiten ▸ Umlaufendes Bad aus, um es zu nutzen)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source> · ink %1</source>
        <translation> · Farbe %1</translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n Schritt</numerusform>
            <numerusform>%n Schritte</numerusform>
        </translation>
    </message>
    <message>
        <location line="+55"/>
        <source>%1[*] — Marbler editor</source>
        <translation>%1[*] — Marbler-Editor</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Rename to “%1”</source>
        <translation>In „%1“ umbenennen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Renamed to “%1”</source>
        <translation>In „%1“ umbenannt</translation>
    </message>
</context>
<context>
    <name>marbler::ui::ExportSettingsDialog</name>
    <message>
        <location filename="../app/shared/ExportSettingsDialog.cpp" line="+14"/>
        <source>Export image</source>
        <translation>Bild exportieren</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>PNG (8-bit sRGB)</source>
        <translation>PNG (8 Bit sRGB)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>JPEG (8-bit sRGB)</source>
        <translation>JPEG (8 Bit sRGB)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TIFF (8-bit sRGB)</source>
        <translation>TIFF (8 Bit sRGB)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TIFF (16-bit sRGB, for print)</source>
        <translation>TIFF (16 Bit sRGB, für den Druck)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OpenEXR (linear half float)</source>
        <translation>OpenEXR (linear, Half-Float)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>SVG (vector)</source>
        <translation>SVG (Vektor)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Separations (a mask per ink and an indexed PNG, in a folder)</source>
        <translation>Farbauszüge (eine Maske je Farbe und ein indiziertes PNG, in einem Ordner)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>For screen and block printers: one greyscale mask per ink and the background, and an indexed PNG whose palette is the inks (marbler render --separations)</source>
        <translation>Für Sieb- und Blockdrucker: eine Graustufenmaske je Farbe und für den Grund sowie ein indiziertes PNG, dessen Palette die Farben sind (marbler render --separations)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The file format; a 16-bit TIFF keeps the smooth gradients of an antialiased render for further grading, EXR keeps linear light</source>
        <translation>Das Dateiformat; ein 16-Bit-TIFF bewahrt die weichen Verläufe eines kantengeglätteten Renderings für die weitere Farbkorrektur, EXR bewahrt lineares Licht</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Format</source>
        <translation>&amp;Format</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The image&apos;s width in the unit beside; the height follows the design&apos;s proportions</source>
        <translation>Die Breite des Bildes in der Einheit daneben; die Höhe folgt den Proportionen des Musters</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+243"/>
        <source>pixels</source>
        <translation>Pixel</translation>
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
        <translation>Zoll</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pixels, or a print size at the resolution below; changing it converts the width</source>
        <translation>Pixel oder eine Druckgröße bei der Auflösung darunter; eine Änderung rechnet die Breite um</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Dots per inch: turns a print size into pixels, and is written into the file</source>
        <translation>Punkte pro Zoll: macht aus einer Druckgröße Pixel und wird in die Datei geschrieben</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (marbler render --aa %2)</source>
        <translation>%1 (marbler render --aa %2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Antialiasing: more samples a pixel give smoother edges and a slower render</source>
        <translation>Kantenglättung: mehr Abtastungen je Pixel ergeben glattere Kanten und ein langsameres Rendering</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Width</source>
        <translation>&amp;Breite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Unit</source>
        <translation>&amp;Einheit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Resolution (dpi)</source>
        <translation>&amp;Auflösung (dpi)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Antialiasing</source>
        <translation>&amp;Kantenglättung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mirror repeat tile (2 × 2): twice the width and height</source>
        <translation>Spiegelrapport-Kachel (2 × 2): doppelte Breite und Höhe</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A seamless tile for print and textiles: the design and its mirror images 2 × 2, so every edge meets its own mirror image (marbler render --repeat mirror)</source>
        <translation>Eine nahtlose Kachel für Druck und Textil: das Muster und seine Spiegelbilder 2 × 2, sodass jede Kante auf ihr eigenes Spiegelbild trifft (marbler render --repeat mirror)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Repeat</source>
        <translation>&amp;Rapport</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Straight repeat tile (2 × 2): the design repeated, twice the width and height</source>
        <translation>Gerader Rapport (2 × 2): das Muster wiederholt, doppelte Breite und Höhe</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>This design&apos;s bath wraps, so the design is a straight-repeat tile: each edge meets the opposite one without a seam. Ticked, the export shows it 2 × 2 (unticked, the plain export is the tile itself)</source>
        <translation>Das Bad dieses Musters läuft an den Rändern um, das Muster ist also eine Kachel mit geradem Rapport: jede Kante trifft nahtlos auf die gegenüberliegende. Angehakt zeigt der Export es 2 × 2 (ohne Haken ist der Export die Kachel selbst)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>SVG: the largest distance between neighbouring vertices of an outline, in design units; larger gives smaller files (marbler svg --tolerance)</source>
        <translation>SVG: der größte Abstand benachbarter Eckpunkte eines Umrisses in Mustereinheiten; größer ergibt kleinere Dateien (marbler svg --tolerance)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Tolerance</source>
        <translation>&amp;Toleranz</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Convert to printer profile (CMYK TIFF)…</source>
        <translation>In Druckerprofil umwandeln (CMYK-TIFF)…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Converts the TIFF from sRGB to the CMYK colours of a printer&apos;s ICC profile, which the print shop gives, and embeds it (marbler render --icc)</source>
        <translation>Wandelt das TIFF von sRGB in die CMYK-Farben des ICC-Profils eines Druckers um, das die Druckerei liefert, und bettet es ein (marbler render --icc)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the printer&apos;s .icc file</source>
        <translation>die .icc-Datei des Druckers</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The CMYK output profile of the press or paper, an .icc or .icm file</source>
        <translation>Das CMYK-Ausgabeprofil der Druckmaschine oder des Papiers, eine .icc- oder .icm-Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C&amp;hoose…</source>
        <translation>&amp;Wählen…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose the printer&apos;s ICC profile</source>
        <translation>Das ICC-Profil des Druckers wählen</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Perceptual (default: the whole image fitted to the press)</source>
        <translation>Wahrnehmungsorientiert (Standard: das ganze Bild an die Druckmaschine angepasst)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Relative colorimetric (exact where printable)</source>
        <translation>Relativ farbmetrisch (genau, wo druckbar)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Saturation (vivid, for graphics)</source>
        <translation>Sättigung (lebhaft, für Grafiken)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Absolute colorimetric (proofing, paper white kept)</source>
        <translation>Absolut farbmetrisch (Proof, Papierweiß bleibt)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How colours the press cannot print are brought into its range (marbler render --intent)</source>
        <translation>Wie Farben, die die Druckmaschine nicht drucken kann, in ihren Umfang gebracht werden (marbler render --intent)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>C&amp;olours</source>
        <translation>F&amp;arben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Printer profile</source>
        <translation>&amp;Druckerprofil</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Intent</source>
        <translation>&amp;Priorität</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>8-bit coverage (antialiased edges)</source>
        <translation>8-Bit-Deckung (geglättete Kanten)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1-bit (on or off, for screens)</source>
        <translation>1 Bit (an oder aus, für Siebe)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Separations: each mask&apos;s pixels as the share of the ink in them, or on where at least half the pixel is the ink (marbler render --mask-bits)</source>
        <translation>Farbauszüge: jedes Maskenpixel als Anteil der Farbe darin, oder an, wo mindestens das halbe Pixel die Farbe ist (marbler render --mask-bits)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Masks</source>
        <translation>&amp;Masken</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Image</source>
        <translation>Bild</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Object view (as shown)</source>
        <translation>Objektansicht (wie gezeigt)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cross-section</source>
        <translation>Querschnitt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The design on its object, as the view shows it, or a flat cut through the block</source>
        <translation>Das Muster auf seinem Objekt, wie die Ansicht es zeigt, oder ein ebener Schnitt durch den Block</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>x (a y-z plane)</source>
        <translation>x (eine y-z-Ebene)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>y (an x-z plane)</source>
        <translation>y (eine x-z-Ebene)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>z (an x-y plane)</source>
        <translation>z (eine x-y-Ebene)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The axis the cross-section is taken across</source>
        <translation>Die Achse, quer zu der der Querschnitt genommen wird</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Where on its axis the cross-section lies, in design units</source>
        <translation>Wo auf seiner Achse der Querschnitt liegt, in Mustereinheiten</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>across the axis</source>
        <translation>quer zur Achse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A turned cross-section&apos;s normal as x, y, z (e.g. 1, 1, 0); empty: across the axis</source>
        <translation>Die Normale eines gedrehten Querschnitts als x, y, z (z. B. 1, 1, 0); leer: quer zur Achse</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>&amp;Show</source>
        <translation>&amp;Zeigen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A&amp;xis</source>
        <translation>A&amp;chse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Normal</source>
        <translation>&amp;Normale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Position</source>
        <translation>&amp;Position</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>Vector outlines in design units (%L1 × %L2)</source>
        <translation>Vektorumrisse in Mustereinheiten (%L1 × %L2)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%L1 × %L2 pixels</source>
        <translation>%L1 × %L2 Pixel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, the tile of a %L1 × %L2 render</source>
        <translation>, die Kachel eines %L1 × %L2-Renderings</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (%1 × %2 in at %3 dpi)</source>
        <translation> (%1 × %2 Zoll bei %3 dpi)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>The widest that fits is %L1 pixels: type at most that in Width.</source>
        <translation>Die größte passende Breite ist %L1 Pixel: geben Sie unter Breite höchstens diesen Wert ein.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The widest that fits is %L1 %2 at %3 dpi: type at most that in Width, or lower the resolution.</source>
        <translation>Die größte passende Breite ist %L1 %2 bei %3 dpi: geben Sie unter Breite höchstens diesen Wert ein oder verringern Sie die Auflösung.</translation>
    </message>
    <message>
        <location line="+141"/>
        <source>The image is too large</source>
        <translation>Das Bild ist zu groß</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No printer profile</source>
        <translation>Kein Druckerprofil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the printer&apos;s ICC profile (an .icc file from the print shop), or untick Convert to printer profile.</source>
        <translation>Wählen Sie das ICC-Profil des Druckers (eine .icc-Datei der Druckerei) oder entfernen Sie den Haken bei In Druckerprofil umwandeln.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cannot use the printer profile</source>
        <translation>Das Druckerprofil kann nicht verwendet werden</translation>
    </message>
</context>
<context>
    <name>marbler::ui::FavouritesShelf</name>
    <message>
        <location filename="../app/workbench/FavouritesShelf.cpp" line="+59"/>
        <source>&amp;Restore removed favourite</source>
        <translation>Entfernten Favoriten &amp;wiederherstellen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Puts the favourite removed last back on the shelf</source>
        <translation>Legt den zuletzt entfernten Favoriten zurück ins Regal</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Favourites</source>
        <translation>Favoriten</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Designs kept aside (F on a cell). Double-click or drag one onto a cell to bring it back.</source>
        <translation>Beiseitegelegte Muster (F auf einer Zelle). Doppelklicken oder auf eine Zelle ziehen holt eines zurück.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Put the removed favourite back (%1)</source>
        <translation>Den entfernten Favoriten zurücklegen (%1)</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Cannot keep the favourite</source>
        <translation>Der Favorit kann nicht behalten werden</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Design %1 kept on the favourites shelf</source>
        <translation>Muster %1 im Favoritenregal behalten</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Put into the grid</source>
        <translation>Ins Raster legen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rename…</source>
        <translation>Umbenennen…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Remove from favourites</source>
        <translation>Aus den Favoriten entfernen</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Cannot rename the favourite</source>
        <translation>Der Favorit kann nicht umbenannt werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 could not be written</source>
        <translation>%1 konnte nicht geschrieben werden</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cannot remove the favourite</source>
        <translation>Der Favorit kann nicht entfernt werden</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Removed “%1” from favourites — Undo (%2)</source>
        <translation>„%1“ aus den Favoriten entfernt — Rückgängig (%2)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Cannot restore the favourite</source>
        <translation>Der Favorit kann nicht wiederhergestellt werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The removed favourite could not be put back from %1 to %2.</source>
        <translation>Der entfernte Favorit konnte nicht von %1 nach %2 zurückgelegt werden.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>“%1” is back on the favourites shelf</source>
        <translation>„%1“ ist wieder im Favoritenregal</translation>
    </message>
</context>
<context>
    <name>marbler::ui::HelpMenu</name>
    <message>
        <location filename="../app/workbench/HelpMenu.cpp" line="+26"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Marbler &amp;guide</source>
        <translation>Marbler-&amp;Anleitung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>What the operators do, how to breed, and every keyboard shortcut</source>
        <translation>Was die Operatoren tun, wie man züchtet, und alle Tastenkürzel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;About Marbler</source>
        <translation>&amp;Über Marbler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Marbler&apos;s version, the libraries it runs with and the renderer in use</source>
        <translation>Marblers Version, die Bibliotheken, mit denen es läuft, und der verwendete Renderer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The Qt toolkit Marbler is built with</source>
        <translation>Das Qt-Toolkit, mit dem Marbler gebaut ist</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Marbler guide</source>
        <translation>Marbler-Anleitung</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 (built with %2)</source>
        <translation>%1 (gebaut mit %2)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>About Marbler</source>
        <translation>Über Marbler</translation>
    </message>
</context>
<context>
    <name>marbler::ui::HistoryDock</name>
    <message>
        <location filename="../app/editor/HistoryDock.cpp" line="+15"/>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Opened</source>
        <translation>Geöffnet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every edit; click one to go back (or forward) to it</source>
        <translation>Jede Bearbeitung; ein Klick geht zu ihr zurück (oder vor)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Edits you undid and then left by making another: click one to go back to it (the edits you leave stay here)</source>
        <translation>Bearbeitungen, die Sie rückgängig gemacht und durch eine neue verlassen haben: ein Klick geht zu ihr zurück (die verlassenen bleiben hier)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Other branches</source>
        <translation>Andere Zweige</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Switched to another branch of the history</source>
        <translation>Zu einem anderen Zweig des Verlaufs gewechselt</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the opened design</source>
        <translation>das geöffnete Muster</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>“%1”</source>
        <translation>„%1“</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>After %1: %n more edit(s), last “%2”</source>
        <translation>
            <numerusform>Nach %1: %n weitere Bearbeitung, zuletzt „%2“</numerusform>
            <numerusform>Nach %1: %n weitere Bearbeitungen, zuletzt „%2“</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Click to switch to this branch</source>
        <translation>Klicken, um zu diesem Zweig zu wechseln</translation>
    </message>
</context>
<context>
    <name>marbler::ui::LineagePanel</name>
    <message>
        <location filename="../app/workbench/LineagePanel.cpp" line="+25"/>
        <source>Lineage</source>
        <translation>Abstammung</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Design</source>
        <translation>Muster</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Made by</source>
        <translation>Entstanden durch</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Parents</source>
        <translation>Eltern</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Generation</source>
        <translation>Generation</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Every generation, branches included, and how the designs came to be. Click a design to select it; double-click a generation to go back to it, or a design of another generation to bring it back into the grid.</source>
        <translation>Jede Generation, Zweige eingeschlossen, und wie die Muster entstanden. Klicken wählt ein Muster; Doppelklick auf eine Generation geht zu ihr zurück, auf ein Muster einer anderen Generation holt es ins Raster zurück.</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>Current designs</source>
        <translation>Aktuelle Muster</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Generations</source>
        <translation>Generationen</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>design %1</source>
        <translation>Muster %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Generation %1</source>
        <translation>Generation %1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>The current generation: its designs are in the grid</source>
        <translation>Die aktuelle Generation: ihre Muster sind im Raster</translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+14"/>
        <source>Branch %1</source>
        <translation>Zweig %1</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>from generation %1</source>
        <translation>aus Generation %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>a new start</source>
        <translation>ein Neubeginn</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Design %1: %2</source>
        <translation>Muster %1: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1
Family: %2</source>
        <translation>%1
Familie: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Changed: %1</source>
        <translation>Geändert: %1</translation>
    </message>
</context>
<context>
    <name>marbler::ui::OpenPlacementDialog</name>
    <message>
        <location filename="../app/workbench/OpenPlacement.cpp" line="-120"/>
        <source>design %1</source>
        <translation>Muster %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>designs %1 and %2</source>
        <translation>Muster %1 und %2</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Where do the opened designs go?</source>
        <translation>Wohin kommen die geöffneten Muster?</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n designs</source>
        <translation>
            <numerusform>%n Muster</numerusform>
            <numerusform>%n Muster</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;b&gt;Opening %1 would replace %2.&lt;/b&gt;</source>
        <translation>&lt;b&gt;%1 zu öffnen würde %2 ersetzen.&lt;/b&gt;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Design %1 is a selected parent.</source>
        <translation>Muster %1 ist ein gewählter Elternteil.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 are selected parents.</source>
        <translation>%1 sind gewählte Eltern.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Either way the grid as it is now stays one generation back (Ctrl+Z).</source>
        <translation>So oder so bleibt das Raster, wie es jetzt ist, eine Generation zurück (Strg+Z).</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Replace the selected cell</source>
        <translation>Die gewählte Zelle &amp;ersetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Replace the selected cells</source>
        <translation>Die gewählten Zellen &amp;ersetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Replace all nine designs</source>
        <translation>Alle neun Muster &amp;ersetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Replace %1</source>
        <translation>%1 &amp;ersetzen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Put the opened designs over %1</source>
        <translation>Die geöffneten Muster über %1 legen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add as a &amp;new generation</source>
        <translation>Als &amp;neue Generation hinzufügen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A new generation that keeps the parents: the opened designs go into free cells, then over designs that are not parents</source>
        <translation>Eine neue Generation, die die Eltern behält: die geöffneten Muster kommen in freie Zellen, dann über Muster, die keine Eltern sind</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Don&apos;t ask again (do the same next time)</source>
        <translation>&amp;Nicht mehr fragen (nächstes Mal dasselbe tun)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remember this choice; opened designs then go where it says without a question</source>
        <translation>Diese Wahl merken; geöffnete Muster kommen dann ohne Frage dorthin</translation>
    </message>
</context>
<context>
    <name>marbler::ui::OperatorActions</name>
    <message>
        <location filename="../app/workbench/OperatorActions.cpp" line="+38"/>
        <source>Alter (1 parent)</source>
        <translation>Abwandeln (1 Elternteil)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Offspring with the parent&apos;s strokes perturbed; the slider sets how much</source>
        <translation>Nachkommen mit gestörten Zügen des Elternteils; der Schieberegler bestimmt, wie stark</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Recombine (2+ parents)</source>
        <translation>Rekombinieren (2+ Eltern)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Offspring that take strokes from each of the parents</source>
        <translation>Nachkommen, die Züge von jedem der Eltern übernehmen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Swap (2 parents)</source>
        <translation>Tauschen (2 Eltern)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One parent&apos;s initial drops with the other&apos;s strokes, both ways</source>
        <translation>Die Anfangstropfen des einen Elternteils mit den Zügen des anderen, in beide Richtungen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Change initial state (1 parent)</source>
        <translation>Anfangszustand ändern (1 Elternteil)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Offspring with new initial drops under the same strokes</source>
        <translation>Nachkommen mit neuen Anfangstropfen unter denselben Zügen</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>How far %1 moves the strokes: 0 % barely, 100 % a lot</source>
        <translation>Wie weit %1 die Züge verschiebt: 0 % kaum, 100 % viel</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+4"/>
        <location line="+2"/>
        <source> Strength %1 % </source>
        <translation> Stärke %1 % </translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 follows when this generation has rendered</source>
        <translation>%1 folgt, wenn diese Generation gerendert ist</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>&amp;Steer by my picks</source>
        <translation>Nach meiner Auswahl &amp;steuern</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Offspring are drawn from many candidates and ranked by what your picks so far say; the status line tells why</source>
        <translation>Nachkommen werden aus vielen Kandidaten gezogen und danach gereiht, was Ihre bisherige Auswahl sagt; die Statuszeile nennt den Grund</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Less like this</source>
        <translation>&amp;Weniger davon</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Marks the selected designs as unlike what you have in mind: steering moves away from them</source>
        <translation>Markiert die gewählten Muster als unähnlich zu dem, was Sie suchen: das Steuern entfernt sich von ihnen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Less like this: click the designs you do not want first</source>
        <translation>Weniger davon: klicken Sie zuerst die Muster an, die Sie nicht wollen</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>%n design(s) no longer marked less like this</source>
        <translation>
            <numerusform>%n Muster nicht mehr als „weniger davon“ markiert</numerusform>
            <numerusform>%n Muster nicht mehr als „weniger davon“ markiert</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n design(s) marked less like this: the next generation moves away from them</source>
        <translation>
            <numerusform>%n Muster als „weniger davon“ markiert: die nächste Generation entfernt sich davon</numerusform>
            <numerusform>%n Muster als „weniger davon“ markiert: die nächste Generation entfernt sich davon</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>marbler::ui::PaletteEditor</name>
    <message>
        <location filename="../app/editor/PaletteEditor.cpp" line="+68"/>
        <source>Turkish ebru</source>
        <translation>Türkisches Ebru</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Florentine</source>
        <translation>Florentiner</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Suminagashi</source>
        <translation>Suminagashi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ocean</source>
        <translation>Ozean</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Autumn</source>
        <translation>Herbst</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>&amp;Bleed</source>
        <translation>&amp;Verlaufen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Soft ink edges: the width of the blend between inks, in design units (0: sharp)</source>
        <translation>Weiche Farbränder: die Breite des Übergangs zwischen Farben in Mustereinheiten (0: scharf)</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Ink %1: click to lay it with the tools, double-click to change its colour</source>
        <translation>Farbe %1: klicken, um sie mit den Werkzeugen zu legen, doppelklicken, um ihre Farbe zu ändern</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Change colour…</source>
        <translation>Farbe ändern…</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+68"/>
        <location line="+8"/>
        <source>Delete ink</source>
        <translation>Farbe löschen</translation>
    </message>
    <message>
        <location line="-64"/>
        <source>Add an ink to the palette</source>
        <translation>Der Palette eine Farbe hinzufügen</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Delete the current ink from the palette (asks first when steps lay it)</source>
        <translation>Die aktuelle Farbe aus der Palette löschen (fragt zuerst, wenn Schritte sie legen)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Presets</source>
        <translation>Vorlagen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replace the inks and the bath with a named palette (one undo step)</source>
        <translation>Die Farben und das Bad durch eine benannte Palette ersetzen (ein Rückgängig-Schritt)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The background (the bare bath): click to change its colour</source>
        <translation>Der Hintergrund (das leere Bad): klicken, um seine Farbe zu ändern</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Ink %1 is the only ink, and steps lay it: add another ink first.</source>
        <translation>Farbe %1 ist die einzige Farbe, und Schritte legen sie: fügen Sie zuerst eine andere Farbe hinzu.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>1 step lays ink %1.</source>
        <translation>1 Schritt legt Farbe %1.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 steps lay ink %2.</source>
        <translation>%1 Schritte legen Farbe %2.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Delete it and lay them with ink %1, the nearest colour, instead?</source>
        <translation>Sie löschen und die Schritte stattdessen mit Farbe %1, der nächsten Farbe, legen?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Delete and re-map</source>
        <translation>&amp;Löschen und neu zuordnen</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Background colour</source>
        <translation>Hintergrundfarbe</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Colour of ink %1</source>
        <translation>Farbe von Farbe %1</translation>
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
        <translation>Letter (8,5 × 11 Zoll)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Square (300 × 300 mm)</source>
        <translation>Quadrat (300 × 300 mm)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>New marbled paper</source>
        <translation>Neues Marmorpapier</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Custom size</source>
        <translation>Eigene Größe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The sheet the paper is made for; the design is measured in its millimetres (marbler paper --size)</source>
        <translation>Der Bogen, für den das Papier gemacht wird; das Muster wird in seinen Millimetern gemessen (marbler paper --size)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The sheet&apos;s width in millimetres</source>
        <translation>Die Breite des Bogens in Millimetern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The sheet&apos;s height in millimetres</source>
        <translation>Die Höhe des Bogens in Millimetern</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Inks, one layer of drops each, each later one smaller (marbler paper --colors)</source>
        <translation>Farben, je eine Schicht Tropfen, jede spätere kleiner (marbler paper --colors)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Combing passes along the sheet, each weaker than the one before (marbler paper --passes)</source>
        <translation>Kammdurchgänge entlang des Bogens, jeder schwächer als der vorige (marbler paper --passes)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Pastel inks on a white bath</source>
        <translation>&amp;Pastellfarben auf weißem Bad</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pale, soft inks instead of random ones on cream (marbler paper --pastel)</source>
        <translation>Blasse, weiche Farben statt zufälliger Farben auf Creme (marbler paper --pastel)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Golden-ratio drops, wrapping (the post&apos;s)</source>
        <translation>Tropfen im Goldenen Schnitt, umlaufend (Rezept des Beitrags)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Classic drops on cream</source>
        <translation>Klassische Tropfen auf Creme</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>marbler paper --recipe post or classic</source>
        <translation>marbler paper --recipe post oder classic</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The same seed and options make the same paper (marbler paper --seed)</source>
        <translation>Derselbe Startwert und dieselben Optionen ergeben dasselbe Papier (marbler paper --seed)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Sheet</source>
        <translation>Bo&amp;gen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Width</source>
        <translation>&amp;Breite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Height</source>
        <translation>&amp;Höhe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Colours</source>
        <translation>&amp;Farben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Combing &amp;passes</source>
        <translation>Kamm&amp;durchgänge</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Recipe</source>
        <translation>&amp;Rezept</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S&amp;eed</source>
        <translation>&amp;Startwert</translation>
    </message>
</context>
<context>
    <name>marbler::ui::ParamForm</name>
    <message>
        <location filename="../app/editor/ParamForm.cpp" line="+210"/>
        <source>The parameters of the selected step</source>
        <translation>Die Parameter des gewählten Schritts</translation>
    </message>
    <message>
        <location line="+77"/>
        <source> [format version %1]</source>
        <translation> [Formatversion %1]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>
In the file: &quot;%1&quot;</source>
        <translation>
In der Datei: „%1“</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Ink %1</source>
        <translation>Farbe %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>x y; x y; ... (2 to %1 points)</source>
        <translation>x y; x y; ... (2 bis %1 Punkte)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>all 1 (a mouse&apos;s stroke)</source>
        <translation>alle 1 (Zug mit der Maus)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>How many teeth: more or fewer over the same span</source>
        <translation>Wie viele Zähne: mehr oder weniger über dieselbe Spanne</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+157"/>
        <source>The distance between two teeth, about the same middle</source>
        <translation>Der Abstand zweier Zähne, um dieselbe Mitte</translation>
    </message>
    <message>
        <location line="-156"/>
        <source>Count</source>
        <translation>Anzahl</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spacing</source>
        <translation>Abstand</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>positions, increasing</source>
        <translation>Positionen, aufsteigend</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>
Drag to see the change as you go</source>
        <translation>
Ziehen zeigt die Änderung sofort</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>The mean distance between the teeth, which are unevenly spaced: a new spacing spaces them evenly</source>
        <translation>Der mittlere Abstand der ungleichmäßig verteilten Zähne: ein neuer Abstand verteilt sie gleichmäßig</translation>
    </message>
    <message>
        <location line="+104"/>
        <source>%1: point %2 (&quot;%3&quot;) is not two numbers &quot;x y&quot;</source>
        <translation>%1: Punkt %2 („%3“) sind nicht zwei Zahlen „x y“</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: point %2 is the same as point %3; consecutive points must differ</source>
        <translation>%1: Punkt %2 ist gleich Punkt %3; aufeinanderfolgende Punkte müssen sich unterscheiden</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: %2 points; a path has 2 to %3</source>
        <translation>%1: %2 Punkte; ein Pfad hat 2 bis %3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: value %2 (&quot;%3&quot;) is not a number</source>
        <translation>%1: Wert %2 („%3“) ist keine Zahl</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: value %2 (%3) %4</source>
        <translation>%1: Wert %2 (%3) %4</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: %2 values for %3 path points; give one a point, or none for all 1</source>
        <translation>%1: %2 Werte für %3 Pfadpunkte; geben Sie einen je Punkt an oder keinen für alle 1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: this stroke would need more than %2 integration steps; split it into shorter strokes</source>
        <translation>%1: dieser Zug bräuchte mehr als %2 Integrationsschritte; teilen Sie ihn in kürzere Züge</translation>
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
        <translation> Neue Population: </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>2D designs</source>
        <translation>2D-Muster</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Solid designs</source>
        <translation>Räumliche Muster</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>What a new random population holds: flat marbling or solid (volume) marbling</source>
        <translation>Was eine neue zufällige Population enthält: flaches Marmorieren oder räumliches (Volumen-)Marmorieren</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>What File ▸ New random population (%1) makes</source>
        <translation>Was Datei ▸ Neue zufällige Population (%1) erzeugt</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The pattern family of a new random population, or a mix of the craft&apos;s families</source>
        <translation>Die Musterfamilie einer neuen zufälligen Population oder eine Mischung der Familien des Handwerks</translation>
    </message>
    <message>
        <location line="+7"/>
        <source> Show on: </source>
        <translation> Zeigen auf: </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The object the designs are shown on (drag in a cell to turn it): a built-in or a mesh file; flat designs also flat</source>
        <translation>Das Objekt, auf dem die Muster gezeigt werden (in einer Zelle ziehen dreht es): ein eingebautes oder eine Mesh-Datei; flache Muster auch flach</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Flat</source>
        <translation>Flach</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Flat designs shown flat</source>
        <translation>Flache Muster flach gezeigt</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Mesh file…</source>
        <translation>Mesh-Datei…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show the designs on an OBJ, STL, PLY or glTF file</source>
        <translation>Die Muster auf einer OBJ-, STL-, PLY- oder glTF-Datei zeigen</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cannot show the mesh</source>
        <translation>Das Mesh kann nicht gezeigt werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1

The designs stay on what they were shown on.</source>
        <translation>%1

Die Muster bleiben auf dem, worauf sie gezeigt wurden.</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Mixed families</source>
        <translation>Gemischte Familien</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every cell a different family of the craft (and some free designs)</source>
        <translation>Jede Zelle eine andere Familie des Handwerks (und einige freie Muster)</translation>
    </message>
</context>
<context>
    <name>marbler::ui::PopulationModel</name>
    <message>
        <location filename="../app/workbench/PopulationModel.cpp" line="+24"/>
        <source>Empty workbench</source>
        <translation>Leere Werkbank</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>%1 needs %2 or more parents</source>
        <translation>%1 braucht %2 oder mehr Eltern</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 needs 1 parent</source>
        <translation>%1 braucht 1 Elternteil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 needs exactly %2 parents</source>
        <translation>%1 braucht genau %2 Eltern</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: there are no designs yet; make a new random population or open designs</source>
        <translation>%1: noch keine Muster; erzeugen Sie eine neue zufällige Population oder öffnen Sie Muster</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: click a design to pick it</source>
        <translation>%1: klicken Sie ein Muster an, um es zu wählen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: click %2 designs</source>
        <translation>%1: klicken Sie %2 Muster an</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>two</source>
        <translation>zwei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2 is picked, click another design</source>
        <translation>%1: %2 ist gewählt, klicken Sie ein weiteres Muster an</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2 are picked, click one to let it go</source>
        <translation>%1: %2 sind gewählt, klicken Sie eines an, um es freizugeben</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 has no room for offspring: every design is a parent, click one to let it go</source>
        <translation>%1 hat keinen Platz für Nachkommen: jedes Muster ist ein Elternteil, klicken Sie eines an, um es freizugeben</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 needs two parents of the same kind (flat/solid): one picked design is flat, the other solid</source>
        <translation>%1 braucht zwei Eltern derselben Art (flach/räumlich): ein gewähltes Muster ist flach, das andere räumlich</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 needs parents of the same kind (flat/solid): the picked designs mix flat and solid ones</source>
        <translation>%1 braucht Eltern derselben Art (flach/räumlich): die gewählten Muster mischen flache und räumliche</translation>
    </message>
    <message>
        <location line="+76"/>
        <source>%1 of 1 parent</source>
        <translation>%1 von 1 Elternteil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 of %2 parents</source>
        <translation>%1 von %2 Eltern</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>Design %1&apos;s palette is locked, and colourways change only the palette: unlock it first</source>
        <translation>Die Palette von Muster %1 ist gesperrt, und Farbvarianten ändern nur die Palette: entsperren Sie sie zuerst</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Colourways of 1 parent</source>
        <translation>Farbvarianten von 1 Elternteil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Colourways mixed from %1 parents</source>
        <translation>Farbvarianten gemischt aus %1 Eltern</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>New %1 population</source>
        <translation>Neue Population: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>New random solid population</source>
        <translation>Neue zufällige räumliche Population</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>New random population</source>
        <translation>Neue zufällige Population</translation>
    </message>
    <message>
        <location line="+196"/>
        <source>%1 (branch %2)</source>
        <translation>%1 (Zweig %2)</translation>
    </message>
    <message>
        <location line="+109"/>
        <source>generation %1 of the session</source>
        <translation>Generation %1 der Sitzung</translation>
    </message>
</context>
<context>
    <name>marbler::ui::RenameDialog</name>
    <message>
        <location filename="../app/shared/RenameDialog.cpp" line="+17"/>
        <source>Rename design</source>
        <translation>Muster umbenennen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The design&apos;s name: shown under it, offered as its file name, kept in the file</source>
        <translation>Der Name des Musters: wird darunter gezeigt, als Dateiname vorgeschlagen und in der Datei gespeichert</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A note for yourself (optional)</source>
        <translation>Eine Notiz für Sie selbst (optional)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shown in the design&apos;s tooltip and kept in its file (meta.note)</source>
        <translation>Wird im Tooltip des Musters gezeigt und in seiner Datei gespeichert (meta.note)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>N&amp;ote:</source>
        <translation>No&amp;tiz:</translation>
    </message>
</context>
<context>
    <name>marbler::ui::RendererMenu</name>
    <message>
        <location filename="../app/workbench/RendererMenu.cpp" line="+19"/>
        <source>&amp;Renderer</source>
        <translation>&amp;Renderer</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Renderer: &amp;Automatic</source>
        <translation>Renderer: &amp;Automatisch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OpenGL on a graphics card; the CPU where OpenGL is a software rasteriser (such as llvmpipe) or missing, since the CPU renderer is faster there</source>
        <translation>OpenGL auf einer Grafikkarte; die CPU, wo OpenGL ein Software-Rasterizer (wie llvmpipe) ist oder fehlt, da der CPU-Renderer dort schneller ist</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Renderer: &amp;GPU</source>
        <translation>Renderer: &amp;GPU</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Always render with OpenGL shaders, even on a software rasteriser (the CPU where there is no OpenGL at all)</source>
        <translation>Immer mit OpenGL-Shadern rendern, auch auf einem Software-Rasterizer (die CPU, wo es gar kein OpenGL gibt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Renderer: &amp;CPU</source>
        <translation>Renderer: &amp;CPU</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Always render with the CPU renderer on every core; solid objects are still rasterised by OpenGL where it exists, and coloured by the CPU</source>
        <translation>Immer mit dem CPU-Renderer auf allen Kernen rendern; räumliche Objekte rastert weiterhin OpenGL, wo es vorhanden ist, und die CPU färbt sie</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1=%2 is set, which overrides this setting</source>
        <translation>%1=%2 ist gesetzt und hat Vorrang vor dieser Einstellung</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Rendering with %1</source>
        <translation>Rendern mit %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rendering on the %1</source>
        <translation>Rendern auf der %1</translation>
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
        <translation>Im Ordner zeigen</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>No file manager opened %1; the file&apos;s path is copied to the clipboard: %2</source>
        <translation>Kein Dateimanager hat %1 geöffnet; der Pfad der Datei wurde in die Zwischenablage kopiert: %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open %1 in the file manager</source>
        <translation>%1 im Dateimanager öffnen</translation>
    </message>
</context>
<context>
    <name>marbler::ui::SectionControls</name>
    <message>
        <location filename="../app/shared/SectionControls.cpp" line="+52"/>
        <source>Section</source>
        <translation>Schnitt</translation>
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
        <translation>Die Achse, quer zu der der Querschnitt liegt; Klicks darauf setzen die 3D-Werkzeuge</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Tilt</source>
        <translation>Neigung</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Tilts the section away from its axis (degrees): strokes drawn on it are placed on the tilted plane</source>
        <translation>Neigt den Schnitt von seiner Achse weg (Grad): darauf gezeichnete Züge liegen in der geneigten Ebene</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Turns the tilt about the section&apos;s axis (degrees)</source>
        <translation>Dreht die Neigung um die Achse des Schnitts (Grad)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Turn</source>
        <translation>Drehung</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Normal</source>
        <translation>Normale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>across the axis</source>
        <translation>quer zur Achse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The section&apos;s normal as x, y, z (e.g. 1, 1, 0), Enter to turn the section to it; empty: across the axis</source>
        <translation>Die Normale des Schnitts als x, y, z (z. B. 1, 1, 0), Eingabe dreht den Schnitt dorthin; leer: quer zur Achse</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Where along its axis the cross-section is cut (PgUp / PgDn move it)</source>
        <translation>Wo entlang seiner Achse der Querschnitt liegt (Bild↑ / Bild↓ verschieben ihn)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Where the cross-section is cut, in design units along its axis (or normal)</source>
        <translation>Wo der Querschnitt liegt, in Mustereinheiten entlang seiner Achse (oder Normalen)</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Mesh file…</source>
        <translation>Mesh-Datei…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The object the design is shown on (drag the object to turn it)</source>
        <translation>Das Objekt, auf dem das Muster gezeigt wird (Ziehen am Objekt dreht es)</translation>
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
        <translation>Das Muster auf einem Mesh zeigen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Meshes (*.obj *.ply *.stl *.off *.gltf *.glb);;All files (*)</source>
        <translation>Meshes (*.obj *.ply *.stl *.off *.gltf *.glb);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>marbler::ui::SessionStore</name>
    <message>
        <location filename="../app/workbench/SessionStore.cpp" line="+86"/>
        <source>%1 could not be moved to %2; it stays where it is</source>
        <translation>%1 konnte nicht nach %2 verschoben werden; es bleibt, wo es ist</translation>
    </message>
</context>
<context>
    <name>marbler::ui::SessionsController</name>
    <message>
        <location filename="../app/workbench/SessionsController.cpp" line="+25"/>
        <source>&amp;New session</source>
        <translation>Neue Si&amp;tzung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start a new breeding session with a random population of the kind shown; this one stays kept under File ▸ Sessions</source>
        <translation>Eine neue Zuchtsitzung mit einer zufälligen Population der gezeigten Art beginnen; diese bleibt unter Datei ▸ Sitzungen aufbewahrt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Sessions…</source>
        <translation>&amp;Sitzungen…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every breeding session is kept: resume, rename or delete one</source>
        <translation>Jede Zuchtsitzung wird aufbewahrt: setzen Sie eine fort, benennen Sie sie um oder löschen Sie sie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Resume session</source>
        <translation>Sitzung &amp;fortsetzen</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>A generation of the session could not be read back: %1</source>
        <translation>Eine Generation der Sitzung konnte nicht zurückgelesen werden: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cannot save the session</source>
        <translation>Die Sitzung kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The breeding session could not be saved, so it would not survive a crash; keep the designs you like as favourites.

%1</source>
        <translation>Die Zuchtsitzung konnte nicht gespeichert werden und würde einen Absturz nicht überstehen; behalten Sie die Muster, die Ihnen gefallen, als Favoriten.

%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The session could not be saved: %1</source>
        <translation>Die Sitzung konnte nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Cannot start a new session</source>
        <translation>Eine neue Sitzung kann nicht begonnen werden</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Started a new session “%1”</source>
        <translation>Neue Sitzung „%1“ begonnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Started a new session “%1”; “%2” is kept under File ▸ Sessions</source>
        <translation>Neue Sitzung „%1“ begonnen; „%2“ bleibt unter Datei ▸ Sitzungen</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>No other sessions</source>
        <translation>Keine anderen Sitzungen</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot resume the session</source>
        <translation>Die Sitzung kann nicht fortgesetzt werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>There is no kept session %1 any more.</source>
        <translation>Es gibt keine aufbewahrte Sitzung %1 mehr.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Resumed “%1” at generation %2</source>
        <translation>„%1“ bei Generation %2 fortgesetzt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Resumed “%1” at generation %2; “%3” is kept under File ▸ Sessions</source>
        <translation>„%1“ bei Generation %2 fortgesetzt; „%3“ bleibt unter Datei ▸ Sitzungen</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Cannot rename the session</source>
        <translation>Die Sitzung kann nicht umbenannt werden</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The session being bred cannot be deleted; resume another one first</source>
        <translation>Die Sitzung, in der gerade gezüchtet wird, kann nicht gelöscht werden; setzen Sie zuerst eine andere fort</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cannot delete the session</source>
        <translation>Die Sitzung kann nicht gelöscht werden</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot bring back the session</source>
        <translation>Die Sitzung kann nicht zurückgeholt werden</translation>
    </message>
</context>
<context>
    <name>marbler::ui::SessionsDialog</name>
    <message>
        <location filename="../app/workbench/SessionsDialog.cpp" line="+25"/>
        <source>Marbler — sessions</source>
        <translation>Marbler — Sitzungen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Every breeding session is kept, however Marbler was started. Resume one to go on where it was left; the one being bred stays kept.</source>
        <translation>Jede Zuchtsitzung wird aufbewahrt, wie auch immer Marbler gestartet wurde. Setzen Sie eine fort, um dort weiterzumachen, wo sie endete; die laufende bleibt aufbewahrt.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Session</source>
        <translation>Sitzung</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Resume</source>
        <translation>&amp;Fortsetzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Re&amp;name</source>
        <translation>&amp;Umbenennen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Undo delete</source>
        <translation>Löschen &amp;rückgängig</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Deleted “%1”. Undo delete brings it back.</source>
        <translation>„%1“ gelöscht. Löschen rückgängig holt sie zurück.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The session is back.</source>
        <translation>Die Sitzung ist wieder da.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>being bred now — %1</source>
        <translation>wird gerade gezüchtet — %1</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>The session being bred cannot be deleted; resume another one first</source>
        <translation>Die Sitzung, in der gerade gezüchtet wird, kann nicht gelöscht werden; setzen Sie zuerst eine andere fort</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moves the session to the trash; Undo delete brings it back</source>
        <translation>Verschiebt die Sitzung in den Papierkorb; Löschen rückgängig holt sie zurück</translation>
    </message>
</context>
<context>
    <name>marbler::ui::SolidObjectView</name>
    <message>
        <location filename="../app/editor/SolidObjectView.cpp" line="+30"/>
        <source>The design on its object: drag to turn it</source>
        <translation>Das Muster auf seinem Objekt: Ziehen dreht es</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Cannot show the design on this object: %1</source>
        <translation>Das Muster kann auf diesem Objekt nicht gezeigt werden: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The object the flat design is shown on, laid on its texture coordinates</source>
        <translation>Das Objekt, auf dem das flache Muster gezeigt wird, auf seine Texturkoordinaten gelegt</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Mesh file…</source>
        <translation>Mesh-Datei…</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>The design on its object: drag to turn it; drag the block in the corner to turn the cross-section</source>
        <translation>Das Muster auf seinem Objekt: Ziehen dreht es; Ziehen am Block in der Ecke dreht den Querschnitt</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Rendering…</source>
        <translation>Wird gerendert…</translation>
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
        <translation>Marbler — was züchten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;b&gt;What would you like to breed?&lt;/b&gt;&lt;br&gt;Nine random designs start the first generation; pick the ones you like as parents and breed the next.</source>
        <translation>&lt;b&gt;Was möchten Sie züchten?&lt;/b&gt;&lt;br&gt;Neun zufällige Muster beginnen die erste Generation; wählen Sie die, die Ihnen gefallen, als Eltern und züchten Sie die nächste.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Breed &amp;flat (2D) designs</source>
        <translation>&amp;Flache (2D) Muster züchten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Marbled paper: patterns in the plane</source>
        <translation>Marmorpapier: Muster in der Ebene</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Breed &amp;solid (3D) designs on an object</source>
        <translation>&amp;Räumliche (3D) Muster auf einem Objekt züchten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Marbling through a volume, shown on the object chosen beside</source>
        <translation>Marmorieren durch ein Volumen, gezeigt auf dem daneben gewählten Objekt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The object solid designs are shown on</source>
        <translation>Das Objekt, auf dem räumliche Muster gezeigt werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Don&apos;t ask again (the toolbar still changes it)</source>
        <translation>&amp;Nicht mehr fragen (die Werkzeugleiste ändert es weiterhin)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> “%1”</source>
        <translation> „%1“</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Resume the last session%1 (generation %2, %3)</source>
        <translation>Letzte Sitzung%1 &amp;fortsetzen (Generation %2, %3)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>solid</source>
        <translation>räumlich</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>2D</source>
        <translation>2D</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Every generation of the last session, back where you left it</source>
        <translation>Jede Generation der letzten Sitzung, dort, wo Sie aufgehört haben</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Every session is kept; File ▸ Sessions renames and deletes them</source>
        <translation>Jede Sitzung wird aufbewahrt; Datei ▸ Sitzungen benennt sie um und löscht sie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resume &amp;another session:</source>
        <translation>&amp;Andere Sitzung fortsetzen:</translation>
    </message>
</context>
<context>
    <name>marbler::ui::StatusLine</name>
    <message>
        <location filename="../app/workbench/StatusLine.cpp" line="+25"/>
        <source>What the window is doing. Help ▸ About Marbler says which renderer draws the designs.</source>
        <translation>Was das Fenster gerade tut. Hilfe ▸ Über Marbler nennt den Renderer, der die Muster zeichnet.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Ready</source>
        <translation>Bereit</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Rendering %1 of %2…</source>
        <translation>Rendere %1 von %2…</translation>
    </message>
</context>
<context>
    <name>marbler::ui::StepList</name>
    <message>
        <location filename="../app/editor/StepList.cpp" line="+81"/>
        <source>Show the steps of one tool only</source>
        <translation>Nur die Schritte eines Werkzeugs zeigen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All steps</source>
        <translation>Alle Schritte</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The steps of the design, first to last: the inks laid at the start, then the strokes. Drag a step to reorder; untick it to mute it; Ctrl+D duplicates, Del deletes, M mutes. A run of steps of one tool is one row: double-click it or press → to open it, ← to fold it.</source>
        <translation>Die Schritte des Musters vom ersten bis zum letzten: die anfangs gelegten Farben, dann die Züge. Ziehen ordnet einen Schritt um; ohne Haken ist er stumm; Strg+D dupliziert, Entf löscht, M schaltet stumm. Eine Folge von Schritten eines Werkzeugs ist eine Zeile: Doppelklick oder → öffnet sie, ← klappt sie zu.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Duplicate step</source>
        <translation>Schritt &amp;duplizieren</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Add a copy of the selected step after it (Ctrl+D)</source>
        <translation>Eine Kopie des gewählten Schritts dahinter einfügen (Strg+D)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>De&amp;lete step</source>
        <translation>Schritt &amp;löschen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Delete the selected step (Del)</source>
        <translation>Den gewählten Schritt löschen (Entf)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Mute step</source>
        <translation>Schritt &amp;stummschalten</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Leave the selected step out of the design, or put it back (M)</source>
        <translation>Den gewählten Schritt aus dem Muster herausnehmen oder zurücknehmen (M)</translation>
    </message>
    <message>
        <location line="+130"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Step %1: an ink laid at the start</source>
        <translation>Schritt %1: eine anfangs gelegte Farbe</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Step %1</source>
        <translation>Schritt %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 %2 (steps %3–%4)</source>
        <translation>%1 %2 (Schritte %3–%4)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Steps %1–%2: %3 %4, shown as one row (double-click or press → to see them); selecting it selects step %1, its box mutes them all</source>
        <translation>Schritte %1–%2: %3 %4, als eine Zeile gezeigt (Doppelklick oder → zeigt sie); die Auswahl wählt Schritt %1, ihr Kästchen schaltet alle stumm</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The first of %1 %2 (double-click or press ← to fold them)</source>
        <translation>Der erste von %1 %2 (Doppelklick oder ← klappt sie zu)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Muted: left out of the design (tick to put it back)</source>
        <translation>Stumm: aus dem Muster herausgenommen (Haken setzen nimmt ihn zurück)</translation>
    </message>
    <message>
        <location line="+90"/>
        <source>&amp;Fold the group (←)</source>
        <translation>Gruppe &amp;zuklappen (←)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Open the group (→)</source>
        <translation>Gruppe &amp;öffnen (→)</translation>
    </message>
</context>
<context>
    <name>marbler::ui::Timeline</name>
    <message>
        <location filename="../app/editor/Timeline.cpp" line="+45"/>
        <source>&amp;Compare</source>
        <translation>&amp;Vergleichen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The making of the design: drag to see it after any step, part way through a step (0: the bare bath; the right end: the whole design)</source>
        <translation>Die Entstehung des Musters: ziehen, um es nach jedem Schritt oder mitten in einem Schritt zu sehen (0: das leere Bad; das rechte Ende: das ganze Muster)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The second state compared side by side with the first</source>
        <translation>Der zweite Zustand, neben dem ersten verglichen</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+123"/>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <location line="-121"/>
        <source>Play the making of the design, each step growing in; again to stop</source>
        <translation>Die Entstehung des Musters abspielen, jeder Schritt wächst herein; nochmals zum Anhalten</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Compare two states of the making side by side: the second slider picks the other</source>
        <translation>Zwei Zustände der Entstehung nebeneinander vergleichen: der zweite Schieberegler wählt den anderen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Play speed: 1× plays the whole making in at most 12 s (0.6 s a step); faster for a quick look, slower to watch each step ([ and ])</source>
        <translation>Abspielgeschwindigkeit: 1× spielt die ganze Entstehung in höchstens 12 s (0,6 s je Schritt); schneller für einen kurzen Blick, langsamer, um jeden Schritt zu verfolgen ([ und ])</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export animation…</source>
        <translation>Animation exportieren…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write the making of the design as a video, an animated image or PNG frames</source>
        <translation>Die Entstehung des Musters als Video, animiertes Bild oder PNG-Einzelbilder schreiben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The step shown, of all the design&apos;s steps</source>
        <translation>Der gezeigte Schritt von allen Schritten des Musters</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Play slower</source>
        <translation>Langsamer abspielen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Play faster</source>
        <translation>Schneller abspielen</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Stop</source>
        <translation>Anhalten</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Now</source>
        <translation>Jetzt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bare bath</source>
        <translation>Leeres Bad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step %1 of %2</source>
        <translation>Schritt %1 von %2</translation>
    </message>
</context>
<context>
    <name>marbler::ui::ToolOptions</name>
    <message>
        <location filename="../app/editor/ToolOptions.cpp" line="+46"/>
        <source>Pick</source>
        <translation>Auswählen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Line of drops</source>
        <translation>Tropfenreihe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rings</source>
        <translation>Ringe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Scatter</source>
        <translation>Streuen</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Click to pick the ink there and select the step that laid it</source>
        <translation>Klicken wählt die Farbe dort und den Schritt, der sie gelegt hat</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Drag to lay a line of drops from the press to the release</source>
        <translation>Ziehen legt eine Tropfenreihe vom Drücken bis zum Loslassen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Drag from the centre: concentric rings out to the release</source>
        <translation>Von der Mitte ziehen: konzentrische Ringe bis zum Loslassen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Drag from the centre: drops scattered evenly in the circle</source>
        <translation>Von der Mitte ziehen: gleichmäßig im Kreis verstreute Tropfen</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>The palette ink the tool lays</source>
        <translation>Die Palettenfarbe, die das Werkzeug legt</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Ink</source>
        <translation>Farbe</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A clicked drop&apos;s radius (a drag sets it)</source>
        <translation>Der Radius eines geklickten Tropfens (Ziehen legt ihn fest)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Droplet</source>
        <translation>Tröpfchen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The radius of each sprayed droplet</source>
        <translation>Der Radius jedes gesprühten Tröpfchens</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Droplets</source>
        <translation>Tröpfchen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>How many droplets one stroke sprinkles</source>
        <translation>Wie viele Tröpfchen ein Zug versprüht</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Brush</source>
        <translation>Pinsel</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>How far from the stroke droplets land</source>
        <translation>Wie weit vom Zug die Tröpfchen landen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Drops</source>
        <translation>Tropfen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>How many drops the pattern lays</source>
        <translation>Wie viele Tropfen das Muster legt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The distance between the comb&apos;s tines</source>
        <translation>Der Abstand zwischen den Zinken des Kamms</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The length of one period of the wave</source>
        <translation>Die Länge einer Periode der Welle</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>How far the circle moves the ink along its rim (a vortex&apos;s click too)</source>
        <translation>Wie weit der Kreis die Farbe an seinem Rand entlang bewegt (auch der Klick eines Wirbels)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Smaller concentrates the shift near the stroke</source>
        <translation>Kleiner bündelt die Verschiebung nahe am Zug</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A finite centre: 0 winds without end, larger keeps the eye clean</source>
        <translation>Eine endliche Mitte: 0 windet ohne Ende, größer hält das Auge sauber</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>across the section</source>
        <translation>quer zum Schnitt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The axis a solid&apos;s circle or sphere turns about, as x, y, z (e.g. 0, 1, 1); empty: across the section it is drawn on</source>
        <translation>Die Achse, um die sich Kreis oder Kugel eines räumlichen Musters dreht, als x, y, z (z. B. 0, 1, 1); leer: quer zum Schnitt, auf dem gezeichnet wird</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Teeth</source>
        <translation>Zähne</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>How many teeth span the design</source>
        <translation>Wie viele Zähne das Muster überspannen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The tooth profile |sin|^p: small is blunt, large is pointed</source>
        <translation>Das Zahnprofil |sin|^p: klein ist stumpf, groß ist spitz</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cells</source>
        <translation>Zellen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cavity</source>
        <translation>Hohlraum</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The velocity field: a lattice of cells or one cavity</source>
        <translation>Das Geschwindigkeitsfeld: ein Gitter aus Zellen oder ein Hohlraum</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The flow&apos;s speed; its sign is the sense of turning</source>
        <translation>Die Geschwindigkeit der Strömung; ihr Vorzeichen ist der Drehsinn</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>How long the flow runs</source>
        <translation>Wie lange die Strömung läuft</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>How hard the stylus pulls the ink along its path: about the shift on the track; negative pushes it back</source>
        <translation>Wie stark der Stift die Farbe entlang seines Pfads zieht: etwa die Verschiebung auf der Spur; negativ schiebt sie zurück</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>How far to the side of the track the pull reaches: smaller is a finer line</source>
        <translation>Wie weit seitlich der Spur der Zug reicht: kleiner ergibt eine feinere Linie</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>How far ahead of and behind the stylus the bath moves</source>
        <translation>Wie weit vor und hinter dem Stift sich das Bad bewegt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>1 draws with a single stylus; more draws a rake of that many tines</source>
        <translation>1 zeichnet mit einem einzelnen Stift; mehr zeichnet einen Rechen mit so vielen Zinken</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The distance between the rake&apos;s tines (with more than one)</source>
        <translation>Der Abstand zwischen den Zinken des Rechens (bei mehr als einer)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Seed</source>
        <translation>Startwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where sprayed and scattered drops land: the same seed, the same drops</source>
        <translation>Wo gesprühte und gestreute Tropfen landen: derselbe Startwert, dieselben Tropfen</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>Ink %1</source>
        <translation>Farbe %1</translation>
    </message>
    <message>
        <location filename="registry-words.cpp" line="-150"/>
        <source>Drop</source>
        <translation>Tropfen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Click to drop ink of the current colour; drag to set its radius. A drop in a drop pushes the older ink into a ring</source>
        <translation>Klicken tropft Farbe der aktuellen Farbe; Ziehen legt ihren Radius fest. Ein Tropfen im Tropfen drängt die ältere Farbe zu einem Ring</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spray</source>
        <translation>Sprühen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag a brush that sprinkles small droplets along its path</source>
        <translation>Einen Pinsel ziehen, der entlang seines Wegs kleine Tröpfchen versprüht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Line</source>
        <translation>Linie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag a stylus through the ink: the drag&apos;s direction and length</source>
        <translation>Einen Stift durch die Farbe ziehen: Richtung und Länge des Ziehens</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Comb</source>
        <translation>Kamm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag a comb through the ink: the drag&apos;s direction and length</source>
        <translation>Einen Kamm durch die Farbe ziehen: Richtung und Länge des Ziehens</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wave</source>
        <translation>Welle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag a wavy comb: the drag gives its direction and amplitude</source>
        <translation>Einen welligen Kamm ziehen: das Ziehen gibt Richtung und Amplitude</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Circle</source>
        <translation>Kreis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag from the centre: a circular stroke of that radius</source>
        <translation>Von der Mitte ziehen: ein kreisförmiger Zug mit diesem Radius</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag from the centre on the section: a tine moved round a sphere of that radius, turning about the panel&apos;s axis</source>
        <translation>Auf dem Schnitt von der Mitte ziehen: eine Zinke, um eine Kugel dieses Radius bewegt, drehend um die Achse des Bedienfelds</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Vortex</source>
        <translation>Wirbel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag from the centre: a swirl, the drag&apos;s length its strength</source>
        <translation>Von der Mitte ziehen: ein Strudel, die Länge des Ziehens ist seine Stärke</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stretch</source>
        <translation>Dehnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag to stretch the ink between teeth across the design</source>
        <translation>Ziehen dehnt die Farbe zwischen Zähnen quer über das Muster</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Flow</source>
        <translation>Strömung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag out a cell of a steady flow (cells or one cavity)</source>
        <translation>Eine Zelle einer stetigen Strömung aufziehen (Zellen oder ein Hohlraum)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stylus</source>
        <translation>Stift</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Draw a free-hand stroke: a stylus (or a rake) pulled along the path</source>
        <translation>Einen freihändigen Zug zeichnen: ein Stift (oder Rechen), den Pfad entlang gezogen</translation>
    </message>
</context>
<context>
    <name>marbler::ui::WorkbenchWindow</name>
    <message>
        <location filename="../app/workbench/SessionsController.cpp" line="+20"/>
        <source>Cannot resume the last session</source>
        <translation>Die letzte Sitzung kann nicht fortgesetzt werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The session could not be read, so it is not resumed.

%1

%2</source>
        <translation>Die Sitzung konnte nicht gelesen werden und wird daher nicht fortgesetzt.

%1

%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The file could not be moved aside.</source>
        <translation>Die Datei konnte nicht beiseitegelegt werden.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The file is kept as %1.</source>
        <translation>Die Datei wird als %1 aufbewahrt.</translation>
    </message>
    <message>
        <location filename="../app/workbench/Workbench.cpp" line="+156"/>
        <source>Cannot move the saved sessions</source>
        <translation>Die gespeicherten Sitzungen können nicht verschoben werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sessions saved by an earlier Marbler could not be moved into the list of kept sessions; they are left where they are.

%1</source>
        <translation>Von einem früheren Marbler gespeicherte Sitzungen konnten nicht in die Liste der aufbewahrten Sitzungen verschoben werden; sie bleiben, wo sie sind.

%1</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>Started a new session; your previous session “%1” is kept under File ▸ Sessions</source>
        <translation>Eine neue Sitzung wurde begonnen; Ihre vorige Sitzung „%1“ bleibt unter Datei ▸ Sitzungen</translation>
    </message>
    <message>
        <location filename="../app/workbench/WorkbenchEditor.cpp" line="+43"/>
        <source>“%1” is open in an editor already</source>
        <translation>„%1“ ist bereits in einem Editor geöffnet</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>From the editor: %1</source>
        <translation>Aus dem Editor: %1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Recovered “%1”</source>
        <translation>„%1“ wiederhergestellt</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Recover a design</source>
        <translation>Ein Muster wiederherstellen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Marbler stopped before the changes to “%1” were saved (autosaved %2). Open them in the editor?

If not, they are kept for %3 days under File ▸ Recover unsaved designs….</source>
        <translation>Marbler wurde beendet, bevor die Änderungen an „%1“ gespeichert waren (automatisch gesichert %2). Im Editor öffnen?

Wenn nicht, bleiben sie %3 Tage unter Datei ▸ Ungespeicherte Muster wiederherstellen… aufbewahrt.</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Recover unsaved designs</source>
        <translation>Ungespeicherte Muster wiederherstellen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Designs that editors left unsaved when Marbler stopped. Each is kept for %1 days after its last autosave, until you open or discard it.</source>
        <translation>Muster, die Editoren beim Beenden von Marbler ungespeichert ließen. Jedes bleibt %1 Tage nach seiner letzten automatischen Sicherung, bis Sie es öffnen oder verwerfen.</translation>
    </message>
    <message>
        <location line="+10"/>
        <location filename="../app/workbench/WorkbenchWindow.cpp" line="+984"/>
        <source>Open in editor</source>
        <translation>Im Editor öffnen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Discard…</source>
        <translation>Verwerfen…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 — autosaved %2</source>
        <translation>%1 — automatisch gesichert %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Nothing to recover</source>
        <translation>Nichts wiederherzustellen</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Discard a design</source>
        <translation>Ein Muster verwerfen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Discard the unsaved changes to “%1” for good?</source>
        <translation>Die ungespeicherten Änderungen an „%1“ endgültig verwerfen?</translation>
    </message>
    <message>
        <location filename="../app/workbench/WorkbenchGuide.cpp" line="+13"/>
        <source>&lt;h2&gt;Marbler guide&lt;/h2&gt;&lt;p&gt;The grid shows nine designs: one &lt;i&gt;generation&lt;/i&gt;. Breed the next one from the designs you like.&lt;/p&gt;&lt;h3&gt;Pick parents&lt;/h3&gt;&lt;p&gt;Click a design to pick it as a parent (it gets a frame); click it again to let it go. With the keyboard, the arrows move between designs and Space picks. %1 (%2) lets every parent go. Parents stay in their cells; every other cell gets offspring.&lt;/p&gt;&lt;h3&gt;Breed&lt;/h3&gt;&lt;p&gt;Apply an operator from the Breed menu or the toolbar:&lt;/p&gt;&lt;ul&gt;</source>
        <translation>&lt;h2&gt;Marbler-Anleitung&lt;/h2&gt;&lt;p&gt;Das Raster zeigt neun Muster: eine &lt;i&gt;Generation&lt;/i&gt;. Züchten Sie die nächste aus den Mustern, die Ihnen gefallen.&lt;/p&gt;&lt;h3&gt;Eltern wählen&lt;/h3&gt;&lt;p&gt;Klicken Sie ein Muster an, um es als Elternteil zu wählen (es erhält einen Rahmen); ein weiterer Klick gibt es frei. Mit der Tastatur bewegen die Pfeiltasten zwischen den Mustern, die Leertaste wählt. %1 (%2) gibt alle Eltern frei. Eltern bleiben in ihren Zellen; jede andere Zelle erhält Nachkommen.&lt;/p&gt;&lt;h3&gt;Züchten&lt;/h3&gt;&lt;p&gt;Wenden Sie einen Operator aus dem Menü Züchten oder der Werkzeugleiste an:&lt;/p&gt;&lt;ul&gt;</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&lt;/ul&gt;&lt;p&gt;The &lt;b&gt;Strength&lt;/b&gt; slider beside them sets how far %1 moves the strokes, from 0 % (barely) to 100 % (a lot). An operator that cannot run is greyed out; its tooltip says what it needs. Flat (2D) and solid (3D) designs do not breed together.&lt;/p&gt;</source>
        <translation>&lt;/ul&gt;&lt;p&gt;Der Schieberegler &lt;b&gt;Stärke&lt;/b&gt; daneben bestimmt, wie weit %1 die Züge verschiebt, von 0 % (kaum) bis 100 % (viel). Ein Operator, der nicht laufen kann, ist ausgegraut; sein Tooltip sagt, was er braucht. Flache (2D) und räumliche (3D) Muster lassen sich nicht miteinander züchten.&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&lt;h3&gt;Back and forward&lt;/h3&gt;&lt;p&gt;Every change (breeding, a new random population, opening designs, bringing back a favourite) is a new generation, and nothing is lost: &lt;b&gt;%1&lt;/b&gt; (%2) and &lt;b&gt;%3&lt;/b&gt; (%4) step through them. The Lineage panel lists every generation; double-click one to go to it.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Zurück und vor&lt;/h3&gt;&lt;p&gt;Jede Änderung (Züchten, eine neue zufällige Population, Muster öffnen, einen Favoriten zurückholen) ist eine neue Generation, und nichts geht verloren: &lt;b&gt;%1&lt;/b&gt; (%2) und &lt;b&gt;%3&lt;/b&gt; (%4) gehen durch sie hindurch. Das Bedienfeld Abstammung listet jede Generation; ein Doppelklick geht zu ihr.&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&lt;h3&gt;Favourites&lt;/h3&gt;&lt;p&gt;Press F on a design (or right-click it, &lt;i&gt;Keep as favourite&lt;/i&gt;) to keep it on the Favourites shelf, where it is saved as a genome file. Double-click a favourite, or drag it onto a cell, to bring it back.&lt;/p&gt;&lt;h3&gt;The large view&lt;/h3&gt;&lt;p&gt;Double-click a design, or press Enter on it, to see it large. Drag a solid design to turn its object. &lt;i&gt;Save genome…&lt;/i&gt; (%1) writes the design&apos;s genome file; &lt;i&gt;Export image…&lt;/i&gt; (%2) renders it to PNG, TIFF, EXR or JPEG at any size; a PNG or TIFF carries the design&apos;s genome, so it opens again as a design. &lt;i&gt;Copy genome&lt;/i&gt; (%3) puts the genome on the clipboard as text. The status bar then says where the file went, with &lt;i&gt;Show in folder&lt;/i&gt;.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Favoriten&lt;/h3&gt;&lt;p&gt;Drücken Sie F auf einem Muster (oder Rechtsklick, &lt;i&gt;Als Favorit behalten&lt;/i&gt;), um es im Favoritenregal zu behalten, wo es als Genomdatei gespeichert wird. Doppelklicken Sie einen Favoriten oder ziehen Sie ihn auf eine Zelle, um ihn zurückzuholen.&lt;/p&gt;&lt;h3&gt;Die große Ansicht&lt;/h3&gt;&lt;p&gt;Doppelklicken Sie ein Muster oder drücken Sie darauf die Eingabetaste, um es groß zu sehen. Ziehen an einem räumlichen Muster dreht sein Objekt. &lt;i&gt;Genom speichern…&lt;/i&gt; (%1) schreibt die Genomdatei des Musters; &lt;i&gt;Bild exportieren…&lt;/i&gt; (%2) rendert es in beliebiger Größe als PNG, TIFF, EXR oder JPEG; ein PNG oder TIFF trägt das Genom des Musters und öffnet sich daher wieder als Muster. &lt;i&gt;Genom kopieren&lt;/i&gt; (%3) legt das Genom als Text in die Zwischenablage. Die Statusleiste sagt dann, wohin die Datei ging, mit &lt;i&gt;Im Ordner zeigen&lt;/i&gt;.&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>&lt;h3&gt;Opening designs&lt;/h3&gt;&lt;p&gt;File ▸ Open designs, or drop genome files on the window (or PNG and TIFF images Marbler exported, which carry their genomes; a plain image is refused): they go into the selected cells, then free ones. &lt;b&gt;%1&lt;/b&gt; (%2) copies the focused or selected design as genome text, and &lt;b&gt;%3&lt;/b&gt; (%4) puts a genome from the clipboard into the grid the same way. When they would replace designs you are asked whether to replace the selected cells or add them as a new generation that keeps the parents. Dropped on a cell, a file replaces that cell (a parent only after asking). A flat design opened among solid ones (or the reverse) starts a generation of its own kind, since the two kinds cannot breed together; the grid it replaces is one generation back.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Muster öffnen&lt;/h3&gt;&lt;p&gt;Datei ▸ Muster öffnen, oder legen Sie Genomdateien auf dem Fenster ab (oder von Marbler exportierte PNG- und TIFF-Bilder, die ihre Genome tragen; ein gewöhnliches Bild wird abgelehnt): sie kommen in die gewählten Zellen, dann in freie. &lt;b&gt;%1&lt;/b&gt; (%2) kopiert das fokussierte oder gewählte Muster als Genomtext, und &lt;b&gt;%3&lt;/b&gt; (%4) legt ein Genom aus der Zwischenablage auf dieselbe Weise ins Raster. Würden sie Muster ersetzen, werden Sie gefragt, ob die gewählten Zellen ersetzt werden oder eine neue Generation entsteht, die die Eltern behält. Auf eine Zelle abgelegt, ersetzt eine Datei diese Zelle (einen Elternteil erst nach Rückfrage). Ein flaches Muster, unter räumlichen geöffnet (oder umgekehrt), beginnt eine Generation seiner eigenen Art, da beide Arten nicht miteinander züchten; das ersetzte Raster ist eine Generation zurück.&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&lt;h3&gt;Keyboard&lt;/h3&gt;&lt;p&gt;On a design in the grid: the arrows move, Space picks or lets go, Enter opens it large, F keeps it as a favourite, the Menu key opens its menu.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Tastatur&lt;/h3&gt;&lt;p&gt;Auf einem Muster im Raster: die Pfeiltasten bewegen, die Leertaste wählt oder gibt frei, die Eingabetaste öffnet es groß, F behält es als Favorit, die Menütaste öffnet sein Menü.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/workbench/WorkbenchPicture.cpp" line="+15"/>
        <location line="+21"/>
        <source>Cannot marble the picture</source>
        <translation>Das Bild kann nicht marmoriert werden</translation>
    </message>
    <message>
        <location line="-20"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no such file</source>
        <translation>keine solche Datei</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 marbled %2</source>
        <translation>%1 marmoriert %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Marbled %1</source>
        <translation>%1 marmoriert</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Marble a picture</source>
        <translation>Ein Bild marmorieren</translation>
    </message>
    <message>
        <location filename="../app/workbench/WorkbenchWindow.cpp" line="-904"/>
        <source>Marbler designs (*.marble.json *.json *.png *.tif *.tiff);;Genome files (*.marble.json *.json);;Images with a genome (*.png *.tif *.tiff);;All files (*)</source>
        <translation>Marbler-Muster (*.marble.json *.json *.png *.tif *.tiff);;Genomdateien (*.marble.json *.json);;Bilder mit Genom (*.png *.tif *.tiff);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Marbler — evolution workbench</source>
        <translation>Marbler — Evolutionswerkbank</translation>
    </message>
    <message>
        <location line="+24"/>
        <location line="+845"/>
        <source>Brought back a favourite</source>
        <translation>Einen Favoriten zurückgeholt</translation>
    </message>
    <message>
        <location line="-843"/>
        <source>Cannot use the dropped design</source>
        <translation>Das abgelegte Muster kann nicht verwendet werden</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>Cannot show the mesh</source>
        <translation>Das Mesh kann nicht gezeigt werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1

The designs are shown on the %2 instead.</source>
        <translation>%1

Die Muster werden stattdessen auf %2 gezeigt.</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Some favourites could not be read: %1</source>
        <translation>Einige Favoriten konnten nicht gelesen werden: %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Breed</source>
        <translation>&amp;Züchten</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Breeding</source>
        <translation>Züchten</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Open designs…</source>
        <translation>Muster ö&amp;ffnen…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Load genome files, or PNG and TIFF images Marbler wrote, into the selected cells, then free ones; asks before replacing designs</source>
        <translation>Genomdateien oder von Marbler geschriebene PNG- und TIFF-Bilder in die gewählten Zellen laden, dann in freie; fragt, bevor Muster ersetzt werden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>New &amp;design</source>
        <translation>Neues &amp;Muster</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Blank &amp;flat bath</source>
        <translation>Leeres &amp;flaches Bad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Make a flat design by hand in the editor, from a bare bath</source>
        <translation>Im Editor von Hand ein flaches Muster machen, aus einem leeren Bad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Blank &amp;solid block</source>
        <translation>Leerer &amp;räumlicher Block</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Make a solid design by hand in the editor, from a bare block</source>
        <translation>Im Editor von Hand ein räumliches Muster machen, aus einem leeren Block</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Random design</source>
        <translation>&amp;Zufälliges Muster</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A random design of the kind chosen on the tool bar, to edit by hand</source>
        <translation>Ein zufälliges Muster der in der Werkzeugleiste gewählten Art, zum Bearbeiten von Hand</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open in &amp;editor…</source>
        <translation>Im &amp;Editor öffnen…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open a design in the editor</source>
        <translation>Ein Muster im Editor öffnen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cannot open the design</source>
        <translation>Das Muster kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Edit a genome file, or an image carrying a genome, step by step</source>
        <translation>Eine Genomdatei oder ein Bild mit Genom Schritt für Schritt bearbeiten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New random population</source>
        <translation>&amp;Neue zufällige Population</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>New random</source>
        <translation>Neu zufällig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nine new random designs of the kind chosen beside (Ctrl+N)</source>
        <translation>Neun neue zufällige Muster der daneben gewählten Art (Strg+N)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Marble a picture…</source>
        <translation>Ein Bild &amp;marmorieren…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Nine flat designs whose bath is a picture you pick: flows and strokes carry its colours</source>
        <translation>Neun flache Muster, deren Bad ein Bild Ihrer Wahl ist: Strömungen und Züge tragen seine Farben</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>A procedural marbled paper (as marbler paper makes) into the grid, to breed from</source>
        <translation>Ein prozedurales Marmorpapier (wie marbler paper es macht) ins Raster, zum Weiterzüchten</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Back a generation</source>
        <translation>Eine Generation &amp;zurück</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>◀ Back</source>
        <translation>◀ Zurück</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Back to the generation this one grew from (Ctrl+Z)</source>
        <translation>Zurück zur Generation, aus der diese hervorging (Strg+Z)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Forward a generation</source>
        <translation>Eine Generation &amp;vor</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Forward ▶</source>
        <translation>Vor ▶</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Forward to the generation last visited or made from this one (Ctrl+Shift+Z)</source>
        <translation>Vor zur zuletzt besuchten oder aus dieser gemachten Generation (Strg+Umschalt+Z)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Copy design</source>
        <translation>Muster &amp;kopieren</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Copies the focused design (else the first selected one) as genome text</source>
        <translation>Kopiert das fokussierte Muster (sonst das erste gewählte) als Genomtext</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Paste design</source>
        <translation>Muster &amp;einfügen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Puts the genome on the clipboard into the grid, as File ▸ Open does</source>
        <translation>Legt das Genom aus der Zwischenablage ins Raster, wie Datei ▸ Öffnen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Clear &amp;selection</source>
        <translation>Auswahl &amp;aufheben</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&amp;Wildcard cell</source>
        <translation>&amp;Joker-Zelle</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The last offspring cell of each generation is a fresh design of the parents&apos; family</source>
        <translation>Die letzte Nachkommenzelle jeder Generation ist ein frisches Muster aus der Familie der Eltern</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>New population</source>
        <translation>Neue Population</translation>
    </message>
    <message>
        <location line="+143"/>
        <source>%1 · less like this</source>
        <translation>%1 · weniger davon</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>No designs yet: make a new random population (Ctrl+N) or open designs (Ctrl+O)</source>
        <translation>Noch keine Muster: erzeugen Sie eine neue zufällige Population (Strg+N) oder öffnen Sie Muster (Strg+O)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Generation %1: %2 — %3 selected</source>
        <translation>Generation %1: %2 — %3 gewählt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>1 parent</source>
        <translation>1 Elternteil</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 parents</source>
        <translation>%1 Eltern</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> — %1</source>
        <translation> — %1</translation>
    </message>
    <message>
        <location line="+102"/>
        <source>Design %1 cannot be rendered: %2</source>
        <translation>Muster %1 kann nicht gerendert werden: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>An empty cell: open a design (Ctrl+O) or drop a file here</source>
        <translation>Eine leere Zelle: öffnen Sie ein Muster (Strg+O) oder legen Sie hier eine Datei ab</translation>
    </message>
    <message>
        <location line="+38"/>
        <location line="+17"/>
        <source>Cannot breed</source>
        <translation>Züchten nicht möglich</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>Breeding generation %1…</source>
        <translation>Generation %1 wird gezüchtet…</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Breeding cancelled: the generation is as it was</source>
        <translation>Züchten abgebrochen: die Generation ist unverändert</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Bred generation %1 with %2</source>
        <translation>Generation %1 mit %2 gezüchtet</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Cannot make a random population</source>
        <translation>Keine zufällige Population möglich</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Cannot open a design</source>
        <translation>Ein Muster kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>These files could not be loaded; the population is unchanged by them.

%1</source>
        <translation>Diese Dateien konnten nicht geladen werden; die Population bleibt davon unverändert.

%1</translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+143"/>
        <source>design %1</source>
        <translation>Muster %1</translation>
    </message>
    <message>
        <location line="-652"/>
        <source>New marbled &amp;paper…</source>
        <translation>Neues Marmor&amp;papier…</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>&amp;Rename…</source>
        <translation>&amp;Umbenennen…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Names the focused design (else the first selected one) and gives it a note</source>
        <translation>Benennt das fokussierte Muster (sonst das erste gewählte) und gibt ihm eine Notiz</translation>
    </message>
    <message>
        <location line="+453"/>
        <source>Nothing opened: %1 holds no design</source>
        <translation>Nichts geöffnet: %1 enthält kein Muster</translation>
    </message>
    <message>
        <location line="+33"/>
        <location line="+1"/>
        <location line="+75"/>
        <source>solid</source>
        <translation>räumlich</translation>
    </message>
    <message>
        <location line="-76"/>
        <location line="+1"/>
        <location line="+75"/>
        <source>flat</source>
        <translation>flach</translation>
    </message>
    <message>
        <location line="-74"/>
        <location line="+12"/>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>Opened %1 and %2: the %3 designs are a generation of their own, the %4 ones one generation back (%5)</source>
        <translation>%1 und %2 geöffnet: die %3en Muster bilden eine eigene Generation, die %4en liegen eine Generation zurück (%5)</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Nothing opened: the grid is as it was</source>
        <translation>Nichts geöffnet: das Raster ist unverändert</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: only %2 of %3 designs found room in the grid</source>
        <translation>%1: nur %2 von %3 Mustern fanden Platz im Raster</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1: %2 designs start a generation of their own; the %3 designs are one generation back (%4)</source>
        <translation>%1: %2 Muster beginnen eine eigene Generation; die %3 Muster sind eine Generation zurück (%4)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1; the grid before is one generation back (%2)</source>
        <translation>%1; das vorige Raster ist eine Generation zurück (%2)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Open designs</source>
        <translation>Muster öffnen</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Nothing copied: click or select a design first</source>
        <translation>Nichts kopiert: klicken oder wählen Sie zuerst ein Muster</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+268"/>
        <source>Copied %1 to the clipboard as genome text</source>
        <translation>%1 als Genomtext in die Zwischenablage kopiert</translation>
    </message>
    <message>
        <location line="-253"/>
        <source>Cannot make the paper</source>
        <translation>Das Papier kann nicht erzeugt werden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Marbled paper %1 (seed %2)</source>
        <translation>Marmorpapier %1 (Startwert %2)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Nothing pasted: the clipboard holds no Marbler design (%1)</source>
        <translation>Nichts eingefügt: die Zwischenablage enthält kein Marbler-Muster (%1)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Pasted %1</source>
        <translation>%1 eingefügt</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Open a design here…</source>
        <translation>Hier ein Muster öffnen…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open a design</source>
        <translation>Ein Muster öffnen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Deselect parent</source>
        <translation>Elternteil abwählen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Select as parent</source>
        <translation>Als Elternteil wählen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>More like this</source>
        <translation>Mehr davon</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Breeds the next generation from this design alone</source>
        <translation>Züchtet die nächste Generation allein aus diesem Muster</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No longer less like this</source>
        <translation>Nicht mehr weniger davon</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Less like this</source>
        <translation>Weniger davon</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Steering moves the next generations away from this design</source>
        <translation>Die Lenkung führt die nächsten Generationen von diesem Muster weg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open large…</source>
        <translation>Groß öffnen…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Keep as favourite</source>
        <translation>Als Favorit behalten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rename…</source>
        <translation>Umbenennen…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save design…</source>
        <translation>Muster speichern…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy design</source>
        <translation>Muster kopieren</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Lock palette</source>
        <translation>Palette sperren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Operators keep this design&apos;s inks</source>
        <translation>Operatoren behalten die Farben dieses Musters</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lock initial state</source>
        <translation>Anfangszustand sperren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Operators keep this design&apos;s initial drops</source>
        <translation>Operatoren behalten die Anfangstropfen dieses Musters</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lock operations</source>
        <translation>Züge sperren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Operators keep this design&apos;s strokes</source>
        <translation>Operatoren behalten die Züge dieses Musters</translation>
    </message>
    <message>
        <location line="+120"/>
        <source>Nothing to rename: click or select a design first</source>
        <translation>Nichts umzubenennen: klicken oder wählen Sie zuerst ein Muster</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Renamed design %1 to “%2”</source>
        <translation>Muster %1 in „%2“ umbenannt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Renamed design %1 to “%2”: another design of this session is called “%3”</source>
        <translation>Muster %1 in „%2“ umbenannt: ein anderes Muster dieser Sitzung heißt „%3“</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>design %1 of generation %2</source>
        <translation>Muster %1 von Generation %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+3"/>
        <source>Brought back %1</source>
        <translation>%1 zurückgeholt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Brought back %1 into design %2</source>
        <translation>%1 in Muster %2 zurückgeholt</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Resumed the last session at generation %1</source>
        <translation>Letzte Sitzung bei Generation %1 fortgesetzt</translation>
    </message>
</context>
</TS>
