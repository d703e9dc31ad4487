#include "binarydeframer.h"
