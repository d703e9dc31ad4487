#include "binarycodec.h"
