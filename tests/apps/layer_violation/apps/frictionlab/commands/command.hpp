#pragma once
// Stands for the command's own header, which nothing outside apps/frictionlab may include.
