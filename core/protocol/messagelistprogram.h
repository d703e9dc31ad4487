// The messages of core, continued (see messagelist.h for the format): the program part of
// commissioning (issue 18). X-macro list, included only by message.h and message.cpp.
