#include "faconcodec.h"
