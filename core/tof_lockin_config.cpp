// Placeholder: configuration structs of this sensor arrive with its golden model.
