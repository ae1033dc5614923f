WORDS = [
("&Language", "&Dil", "&Sprache"),
("&System language", "&Sistem dili", "&Systemsprache"),
("The window's language from the next start of Marbler", "Marbler'ın bir sonraki açılışından itibaren pencerenin dili", "Die Sprache des Fensters ab dem nächsten Start von Marbler"),
("The language changes when Marbler starts again", "Dil, Marbler yeniden başladığında değişir", "Die Sprache wechselt beim nächsten Start von Marbler"),
]
