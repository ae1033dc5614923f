# Issue 23: the editor's object view, whose corner block turns a solid's cross-section when
# dragged: (English, Turkish, German).
WORDS = [
("The design on its object: drag to turn it; drag the block in the corner to turn the cross-section", "Nesnesi üzerindeki desen: döndürmek için sürükleyin; kesiti döndürmek için köşedeki bloğu sürükleyin", "Das Muster auf seinem Objekt: Ziehen dreht es; Ziehen am Block in der Ecke dreht den Querschnitt"),
]
