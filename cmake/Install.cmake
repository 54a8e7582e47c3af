# placeholder: install rules
