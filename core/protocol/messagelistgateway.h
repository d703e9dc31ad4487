// The messages of core, continued (see messagelist.h for the format): the MQTT gateway
// (fatek-gateway, core/gateway; issue 20). X-macro list, included only by message.h and
// message.cpp.
