// Placeholder until the editor-doc branch lands its implementation.
#include "editor/EditorDocument.h"
