# Issue 26 (Breeding that steers): a design's More like this and Less like this, and a generation
# bred off the window's thread with a box that cancels it: (English, Turkish, German).
WORDS = [
("More like this", "Bunun gibi daha fazla", "Mehr davon"),
("Breeds the next generation from this design alone", "Sonraki nesli yalnızca bu desenden üretir", "Züchtet die nächste Generation allein aus diesem Muster"),
("Less like this", "Bunun gibi daha az", "Weniger davon"),
("No longer less like this", "Artık bunun gibi daha az değil", "Nicht mehr weniger davon"),
("Steering moves the next generations away from this design", "Yönlendirme sonraki nesilleri bu desenden uzaklaştırır", "Die Lenkung führt die nächsten Generationen von diesem Muster weg"),
("Breeding generation %1…", "%1. nesil üretiliyor…", "Generation %1 wird gezüchtet…"),
("Breeding cancelled: the generation is as it was", "Üretim iptal edildi: nesil olduğu gibi kaldı", "Züchten abgebrochen: die Generation ist unverändert"),
]
