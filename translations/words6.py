# Plurals of the tools, after a count ("36 drops"): Turkish keeps the singular after a number.
WORDS = [
("drops", "damla", "Tropfen"),
("sprays", "serpme", "Sprühungen"),
("cylinders", "silindir", "Zylinder"),
("lines", "çizgi", "Linien"),
("combs", "tarak", "Kämme"),
("waves", "dalga", "Wellen"),
("circles", "daire", "Kreise"),
("spheres", "küre", "Kugeln"),
("vortices", "girdap", "Wirbel"),
("stretches", "germe", "Dehnungen"),
("flows", "akış", "Strömungen"),
("stylus strokes", "biz çekişi", "Stiftzüge"),
("styluses", "biz çekişi", "Stiftzüge"),
]
