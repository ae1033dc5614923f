# Issue 28: a session kept as one file per generation, read back when it is needed:
# (English, Turkish, German).
WORDS = [
("generation %1 of the session", "oturumun %1. nesli", "Generation %1 der Sitzung"),
("A generation of the session could not be read back: %1", "Oturumun bir nesli geri okunamadı: %1", "Eine Generation der Sitzung konnte nicht zurückgelesen werden: %1"),
]
