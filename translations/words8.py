# Print delivery (issue 29): the CMYK TIFF for a printer's profile and the separations in Export
# image, and the repeat swatch of a bath that wraps: (English, Turkish, German).
WORDS = [
# The printer's profile: its chooser.
("Printer profile", "Yazıcı profili", "Druckerprofil"),
("ICC profiles (*.icc *.icm);;All files (*)", "ICC profilleri (*.icc *.icm);;Tüm dosyalar (*)", "ICC-Profile (*.icc *.icm);;Alle Dateien (*)"),
# The large view's repeat swatch of a design whose bath wraps.
("Show the design repeated 2 × 2 as its straight repeat, to judge the repeat (R)", "Tekrarı değerlendirmek için deseni düz tekrarıyla 2 × 2 göster (R)", "Das Muster als geraden Rapport 2 × 2 wiederholt zeigen, um den Rapport zu beurteilen (R)"),
("Show the design repeated 2 × 2 as its half-drop repeat, to judge the repeat (R)", "Tekrarı değerlendirmek için deseni yarım kaydırmalı tekrarıyla 2 × 2 göster (R)", "Das Muster als Halbversatz-Rapport 2 × 2 wiederholt zeigen, um den Rapport zu beurteilen (R)"),
("Show the design repeated 2 × 2 as its brick repeat, to judge the repeat (R)", "Tekrarı değerlendirmek için deseni tuğla tekrarıyla 2 × 2 göster (R)", "Das Muster als Ziegel-Rapport 2 × 2 wiederholt zeigen, um den Rapport zu beurteilen (R)"),
# Separations into a folder.
("Export separations into a folder", "Renk ayrımlarını bir klasöre aktar", "Farbauszüge in einen Ordner exportieren"),
(" separations", " renk ayrımları", " Farbauszüge"),
("Folders (*)", "Klasörler (*)", "Ordner (*)"),
("Separations (a mask per ink and an indexed PNG, in a folder)", "Renk ayrımları (her boya için bir maske ve dizinli bir PNG, bir klasörde)", "Farbauszüge (eine Maske je Farbe und ein indiziertes PNG, in einem Ordner)"),
("For screen and block printers: one greyscale mask per ink and the background, and an indexed PNG whose palette is the inks (marbler render --separations)", "Serigrafi ve blok baskıcılar için: her boya ve zemin için bir gri tonlu maske ve paleti boyalar olan dizinli bir PNG (marbler render --separations)", "Für Sieb- und Blockdrucker: eine Graustufenmaske je Farbe und für den Grund sowie ein indiziertes PNG, dessen Palette die Farben sind (marbler render --separations)"),
("8-bit coverage (antialiased edges)", "8 bit kaplama (yumuşatılmış kenarlar)", "8-Bit-Deckung (geglättete Kanten)"),
("1-bit (on or off, for screens)", "1 bit (açık ya da kapalı, serigrafi için)", "1 Bit (an oder aus, für Siebe)"),
("Separations: each mask's pixels as the share of the ink in them, or on where at least half the pixel is the ink (marbler render --mask-bits)", "Renk ayrımları: her maske pikseli içindeki boya payı olarak ya da pikselin en az yarısı boyaysa açık (marbler render --mask-bits)", "Farbauszüge: jedes Maskenpixel als Anteil der Farbe darin, oder an, wo mindestens das halbe Pixel die Farbe ist (marbler render --mask-bits)"),
("&Masks", "&Maskeler", "&Masken"),
# The CMYK TIFF for a printer's profile.
("Convert to printer profile (CMYK TIFF)…", "Yazıcı profiline dönüştür (CMYK TIFF)…", "In Druckerprofil umwandeln (CMYK-TIFF)…"),
("Converts the TIFF from sRGB to the CMYK colours of a printer's ICC profile, which the print shop gives, and embeds it (marbler render --icc)", "TIFF'i sRGB'den matbaanın verdiği yazıcı ICC profilinin CMYK renklerine dönüştürür ve profili içine gömer (marbler render --icc)", "Wandelt das TIFF von sRGB in die CMYK-Farben des ICC-Profils eines Druckers um, das die Druckerei liefert, und bettet es ein (marbler render --icc)"),
("the printer's .icc file", "yazıcının .icc dosyası", "die .icc-Datei des Druckers"),
("The CMYK output profile of the press or paper, an .icc or .icm file", "Baskı makinesinin ya da kağıdın CMYK çıkış profili, bir .icc veya .icm dosyası", "Das CMYK-Ausgabeprofil der Druckmaschine oder des Papiers, eine .icc- oder .icm-Datei"),
("C&hoose…", "&Seç…", "&Wählen…"),
("Choose the printer's ICC profile", "Yazıcının ICC profilini seçin", "Das ICC-Profil des Druckers wählen"),
("Perceptual (default: the whole image fitted to the press)", "Algısal (varsayılan: tüm görüntü baskıya uydurulur)", "Wahrnehmungsorientiert (Standard: das ganze Bild an die Druckmaschine angepasst)"),
("Relative colorimetric (exact where printable)", "Göreli kolorimetrik (basılabilen yerde tam)", "Relativ farbmetrisch (genau, wo druckbar)"),
("Saturation (vivid, for graphics)", "Doygunluk (canlı, grafikler için)", "Sättigung (lebhaft, für Grafiken)"),
("Absolute colorimetric (proofing, paper white kept)", "Mutlak kolorimetrik (prova, kağıt beyazı korunur)", "Absolut farbmetrisch (Proof, Papierweiß bleibt)"),
("How colours the press cannot print are brought into its range (marbler render --intent)", "Baskı makinesinin basamadığı renklerin onun aralığına nasıl getirileceği (marbler render --intent)", "Wie Farben, die die Druckmaschine nicht drucken kann, in ihren Umfang gebracht werden (marbler render --intent)"),
("C&olours", "&Renkler", "F&arben"),
("&Printer profile", "&Yazıcı profili", "&Druckerprofil"),
("&Intent", "&Amaç", "&Priorität"),
("No printer profile", "Yazıcı profili yok", "Kein Druckerprofil"),
("Choose the printer's ICC profile (an .icc file from the print shop), or untick Convert to printer profile.", "Yazıcının ICC profilini (matbaadan bir .icc dosyası) seçin ya da Yazıcı profiline dönüştür seçeneğinin işaretini kaldırın.", "Wählen Sie das ICC-Profil des Druckers (eine .icc-Datei der Druckerei) oder entfernen Sie den Haken bei In Druckerprofil umwandeln."),
("Cannot use the printer profile", "Yazıcı profili kullanılamıyor", "Das Druckerprofil kann nicht verwendet werden"),
]
